#include "client/render/sketch/segment_sketcher.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "client/render/wide_lines.hpp"
#include "common/error.hpp"

namespace inkwire {

using namespace gl;

namespace {

// `n` points evenly spaced by arc length along a polyline.
std::vector<glm::vec3> resample(const std::vector<glm::vec3>& line, int n) {
  std::vector<float> at(line.size(), 0.0f);
  for (size_t i = 1; i < line.size(); ++i) at[i] = at[i - 1] + glm::length(line[i] - line[i - 1]);
  std::vector<glm::vec3> out;
  size_t seg = 0;
  for (int k = 0; k < n; ++k) {
    const float target = at.back() * float(k) / float(n - 1);
    while (seg + 2 < line.size() && at[seg + 1] < target) ++seg;
    const float span = std::max(at[seg + 1] - at[seg], 1e-12f);
    out.push_back(glm::mix(line[seg], line[seg + 1], std::clamp((target - at[seg]) / span, 0.0f, 1.0f)));
  }
  return out;
}

}  // namespace

int UnitLines::bin_of(float length) const {
  for (size_t b = 0; b + 1 < bin_upper.size(); ++b)
    if (length < bin_upper[b]) return int(b);
  return int(bin_upper.size()) - 1;
}

UnitLines make_unit_lines(float diagonal, const PerturbOptions& o, int lines, uint64_t seed) {
  if (lines < 1 || lines > 64 || diagonal <= 0.0f) throw Error("unit lines: bad sizes");
  UnitLines u;
  u.lines = lines;
  // Bins by edge length (fractions of the diagonal), each with a representative length.
  const float upper[] = {0.005f, 0.015f, 0.04f, 0.1f, 1e30f};
  const float typical[] = {0.003f, 0.009f, 0.025f, 0.065f, 0.15f};
  for (int b = 0; b < 5; ++b) {
    u.bin_upper.push_back(upper[b] * diagonal);
    const float length = typical[b] * diagonal;
    // In units of the edge's length: the same absolute wiggle as a stroke of this length.
    PerturbOptions unit;
    unit.amplitude_ratio = perturb_amplitude(length, o) / length;
    unit.amplitude_clamp = unit.amplitude_ratio;
    unit.max_segment = std::clamp(o.max_segment / length, 1.0f / 32.0f, 1.0f);
    const int points = int(std::ceil(1.0f / unit.max_segment)) + 1;
    u.points.push_back(points);
    u.first.push_back(int(u.data.size()));
    for (int l = 0; l < lines; ++l) {
      StrokeRandom random(stroke_seed(seed, uint64_t(b), uint64_t(l)));
      std::vector<glm::vec3> line;
      perturb_stroke({{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {0, 1, 0}}, unit, random, line);
      for (const glm::vec3& p : resample(line, points)) u.data.push_back({p.x, p.y});
    }
  }
  return u;
}

SegmentSketcher::SegmentSketcher() : program_(Program::from_files({"sketch/segments.vert", "sketch/strokes.frag"}, {"WIDE_LINE"})) {}

std::vector<ParamSpec> SegmentSketcher::params() {
  std::vector<ParamSpec> specs = SketchEdgeSource::params(false);
  const std::vector<ParamSpec> own = InkLineStyle::params();
  specs.insert(specs.end(), own.begin(), own.end());
  return specs;
}

void SegmentSketcher::configure(const StyleParams& p) {
  edges_.configure(p);
  ink_.configure(p);
  if (object_) prepare(*object_);
}

void SegmentSketcher::prepare(const SceneObject& object) {
  const bool new_object = object_ != &object;
  object_ = &object;
  edges_.prepare(object);
  if (new_object || !mesh_) mesh_ = std::make_unique<GpuMesh>(object);
  const float diagonal = object.topology.bounds.diagonal();
  unit_lines_ = make_unit_lines(diagonal, ink_.perturb_for(diagonal));
  std::vector<glm::vec4> unit_points;
  for (const glm::vec2& p : unit_lines_.data) unit_points.emplace_back(p, 0.0f, 0.0f);
  unit_texture_ = Texture::data_rows(unit_points);
  by_bin_.assign(unit_lines_.points.size(), {});
  edge_texture_ = Texture::data_rows({});
  vao_ = VertexArray::create();  // no attributes: the shader pulls everything from textures
}

void SegmentSketcher::draw(const FrameState& frame) {
  if (!mesh_) throw Error("SegmentSketcher::draw(): prepare() was not called");
  const Mesh& mesh = object_->mesh;
  const glm::vec3 eye = frame.eye_in_object_space();
  const long step = ink_.boil_step(frame.time_seconds);
  for (auto& bin : by_bin_) bin.clear();
  for (const DrawnEdge& d : edges_.choose(eye)) {
    const Edge& e = object_->topology.edges[d.edge];
    const glm::vec3 a = mesh.positions[e.v0], b = mesh.positions[e.v1];
    glm::vec3 side = glm::cross(b - a, 0.5f * (a + b) - eye);
    const float l = glm::length(side);
    if (l <= 1e-12f) continue;
    // A pseudo-random line of the edge's bin, changing with time.
    const float line = float(stroke_seed(d.edge, uint64_t(step), 91) % uint64_t(unit_lines_.lines));
    by_bin_[size_t(unit_lines_.bin_of(e.length))].push_back({glm::vec4(a, d.opacity), glm::vec4(b, line), glm::vec4(side / l, 0.0f)});
  }
  packed_.clear();
  std::vector<size_t> base(by_bin_.size());
  for (size_t bin = 0; bin < by_bin_.size(); ++bin) {
    base[bin] = packed_.size() / 3;
    for (const EdgeTransform& e : by_bin_[bin]) packed_.insert(packed_.end(), {e.start_and_opacity, e.end_and_line, e.side});
  }
  edge_texture_.update_rows(packed_);

  const glm::mat4 mvp = frame.model_view_projection();
  hlr_.lay_depth(*mesh_, frame);
  HiddenLineRemoval::begin_lines();  // depth test on, writes off
  program_.use();
  program_.set("model_view_projection", mvp);
  program_.set("depth_bias", depth_bias_);
  program_.set("ink", ink_.ink);
  set_wide_line_uniforms(program_, ink_.line_width);
  program_.set("unit_points", 0);
  program_.set("edges", 1);
  unit_texture_.bind(0);
  edge_texture_.bind(1);
  vao_.bind();
  for (size_t bin = 0; bin < by_bin_.size(); ++bin) {
    if (by_bin_[bin].empty()) continue;
    const int points = unit_lines_.points[bin];
    program_.set("points_per_line", points);
    program_.set("first_point", unit_lines_.first[bin]);
    program_.set("first_edge", int(base[bin]));
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(6 * (points - 1) * by_bin_[bin].size()));
  }
  HiddenLineRemoval::end_lines();
}

std::map<std::string, double> SegmentSketcher::counters() const { return edges_.counters(); }

}  // namespace inkwire
