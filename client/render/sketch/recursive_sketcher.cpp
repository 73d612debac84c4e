#include "client/render/sketch/recursive_sketcher.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "common/error.hpp"

namespace inkwire {

using namespace gl;

RecursiveSketcher::RecursiveSketcher() : strokes_(Program::from_files({"sketch/strokes.vert", "sketch/strokes.frag"}, {"WIDE_LINE"})) {}

std::vector<ParamSpec> RecursiveSketcher::params() {
  std::vector<ParamSpec> specs = SketchEdgeSource::params(false);
  const std::vector<ParamSpec> own = {
      int_param("repetitions", "3", 1, 4, "strokes per edge at most (fewer when many edges are drawn)"),
      int_param("stroke_budget", "900", 1, 1000000, "strokes per frame the repetitions aim for"),
      float_param("min_stroke", "0.03", 0, 1, "leave out joined lines shorter than this fraction of the diagonal (specks)"),
      int_param("search_every", "3", 1, 60, "under rotation, find the edges again every this many frames"),
      float_param("stroke_length", "0.3", 0.01, 10, "longest stroke, fraction of the diagonal (longer outlines take several)"),
  };
  specs.insert(specs.end(), own.begin(), own.end());
  const std::vector<ParamSpec> ink = InkLineStyle::params();
  specs.insert(specs.end(), ink.begin(), ink.end());
  return specs;
}

void RecursiveSketcher::configure(const StyleParams& p) {
  edges_.configure(p);
  max_repetitions_ = p.get_int("repetitions");
  stroke_budget_ = p.get_int("stroke_budget");
  search_every_ = p.get_int("search_every");
  max_stroke_ratio_ = p.get_float("stroke_length");
  min_stroke_ratio_ = p.get_float("min_stroke");
  ink_.configure(p);
  if (object_) prepare(*object_);  // thresholds depend on the object's size
}

void RecursiveSketcher::prepare(const SceneObject& object) {
  const bool new_object = object_ != &object;
  object_ = &object;
  if (new_object || !mesh_) mesh_ = std::make_unique<GpuMesh>(object);
  edges_.prepare(object);
  const float diagonal = object.topology.bounds.diagonal();
  perturb_ = ink_.perturb_for(diagonal);
  max_stroke_ = max_stroke_ratio_ * diagonal;
  min_stroke_ = min_stroke_ratio_ * diagonal;
  for (StrokeSet& set : sets_) {
    set.buffer = Buffer::create(0, nullptr, GL_STREAM_DRAW);
    set.vao = VertexArray::create();
    wide_line_attributes(set.vao, set.buffer);
    set.generation = -1;
  }
  glBindVertexArray(0);
  frames_since_search_ = 1 << 30;
}

int RecursiveSketcher::repetitions() const {
  // Fewer repetitions when the outline breaks into many strokes, so the drawing stays light.
  const int per_stroke = stroke_budget_ / std::max<int>(1, int(stroke_count_));
  return std::clamp(per_stroke, 1, max_repetitions_);
}

void RecursiveSketcher::build_set(int set, const FrameState& frame) {
  const Mesh& mesh = object_->mesh;
  const glm::vec3 eye = frame.eye_in_object_space();
  const std::vector<DrawnEdge>& drawn = edges_.drawn();
  chain_edges_.clear();
  for (const DrawnEdge& d : drawn) {
    const Edge& e = object_->topology.edges[d.edge];
    chain_edges_.push_back({e.v0, e.v1, 0});
  }
  // Strokes: chains cut to at most the stroke length, each starting where the last ended;
  // chains shorter than the minimum (specks from a ragged silhouette) are left out. A stroke's
  // opacity is the mean of its edges' (so fading changes it gradually).
  strokes_found_.clear();
  for (const Chain& chain : chains_.build(chain_edges_, mesh.positions.size(), &mesh.positions)) {
    float chain_length = 0.0f;
    for (size_t i = 0; i + 1 < chain.vertices.size(); ++i)
      chain_length += glm::length(mesh.positions[chain.vertices[i + 1]] - mesh.positions[chain.vertices[i]]);
    if (chain_length < min_stroke_) continue;
    Stroke stroke{drawn[chain.edges[0]].edge, 0.0f, {chain.vertices[0]}};
    float length = 0.0f;
    for (size_t i = 0; i < chain.edges.size(); ++i) {
      length += glm::length(mesh.positions[chain.vertices[i + 1]] - mesh.positions[chain.vertices[i]]);
      stroke.opacity += drawn[chain.edges[i]].opacity;
      stroke.vertices.push_back(chain.vertices[i + 1]);
      if (length >= max_stroke_ || i + 1 == chain.edges.size()) {
        stroke.opacity /= float(stroke.vertices.size() - 1);
        strokes_found_.push_back(stroke);
        stroke = {i + 1 < chain.edges.size() ? drawn[chain.edges[i + 1]].edge : 0u, 0.0f, {chain.vertices[i + 1]}};
        length = 0.0f;
      }
    }
  }
  stroke_count_ = strokes_found_.size();

  const int reps = repetitions();
  scratch_.clear();
  for (const Stroke& stroke : strokes_found_) {
    stroke_points_.resize(stroke.vertices.size());
    stroke_sides_.resize(stroke.vertices.size());
    for (size_t i = 0; i < stroke.vertices.size(); ++i) stroke_points_[i] = mesh.positions[stroke.vertices[i]];
    // Wobble across the stroke as the viewer sees it.
    for (size_t i = 0; i < stroke_points_.size(); ++i) {
      const glm::vec3 tangent = stroke_points_[std::min(i + 1, stroke_points_.size() - 1)] - stroke_points_[i ? i - 1 : 0];
      const glm::vec3 side = glm::cross(tangent, stroke_points_[i] - eye);
      const float l = glm::length(side);
      stroke_sides_[i] = l > 1e-12f ? side / l : glm::vec3(0.0f);
    }
    for (int r = 0; r < reps; ++r) {
      StrokeRandom random(stroke_seed(stroke.id, uint64_t(set), uint64_t(r)));
      polyline_.clear();
      perturb_stroke(stroke_points_, stroke_sides_, perturb_, random, polyline_);
      const float o = stroke.opacity * (1.0f - 0.2f * float(r) / float(std::max(1, reps - 1)));
      for (size_t i = 0; i + 1 < polyline_.size(); ++i) append_wide_line(scratch_, polyline_[i], polyline_[i + 1], o, o);
    }
  }
  StrokeSet& s = sets_[size_t(set)];
  s.buffer.upload(scratch_.size() * sizeof(WideLineVertex), scratch_.data());
  s.vertices = scratch_.size();
  s.generation = generation_;
}

void RecursiveSketcher::draw(const FrameState& frame) {
  if (!mesh_) throw Error("RecursiveSketcher::draw(): prepare() was not called");
  // Find the edges again every few frames (the first frame always searches).
  ++frames_since_search_;
  if (frames_since_search_ >= search_every_) {
    edges_.choose(frame.eye_in_object_space());
    ++generation_;
    frames_since_search_ = 0;
  }
  // Boil: one step per 1/boil_hz seconds; the sets are replayed in an order reshuffled every
  // cycle (deterministically, so recordings repeat).
  // Floor division, so times before zero (warm-up frames, scrubbing back) still pick a set.
  const long step = ink_.boil_step(frame.time_seconds);
  const long cycle = step >= 0 ? step / kSets : -((-step + kSets - 1) / kSets);
  const long slot = step - cycle * kSets;  // 0..kSets-1
  std::array<int, kSets> order;
  for (int i = 0; i < kSets; ++i) order[size_t(i)] = i;
  StrokeRandom shuffle(stroke_seed(uint64_t(cycle), 77));
  for (int i = kSets - 1; i > 0; --i) std::swap(order[size_t(i)], order[shuffle.next() % uint64_t(i + 1)]);
  const int set = order[size_t(slot)];
  if (sets_[size_t(set)].generation != generation_) build_set(set, frame);

  const glm::mat4 mvp = frame.model_view_projection();
  hlr_.lay_depth(*mesh_, frame);
  HiddenLineRemoval::begin_lines();  // depth test on, writes off
  strokes_.use();
  strokes_.set("model_view_projection", mvp);
  strokes_.set("depth_bias", depth_bias_);
  strokes_.set("ink", ink_.ink);
  set_wide_line_uniforms(strokes_, ink_.line_width);
  sets_[size_t(set)].vao.bind();
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(sets_[size_t(set)].vertices));
  HiddenLineRemoval::end_lines();
}

std::map<std::string, double> RecursiveSketcher::counters() const {
  std::map<std::string, double> c = edges_.counters();
  if (object_) c.insert({{"strokes", double(stroke_count_)}, {"repetitions", double(repetitions())}});
  return c;
}

}  // namespace inkwire
