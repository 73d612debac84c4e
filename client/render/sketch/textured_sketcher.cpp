#include "client/render/sketch/textured_sketcher.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "client/render/backdrop.hpp"
#include "client/render/sketch/perturb.hpp"
#include "common/error.hpp"
#include "common/noise.hpp"

namespace inkwire {

using namespace gl;

namespace {

constexpr int kToothSize = 512;          // as the paper backdrop is generated
constexpr float kPressurePeriod = 0.12f;  // pressure changes over about this share of the diagonal

glm::vec3 ink_of(Medium medium) {
  switch (medium) {
    case Medium::Charcoal: return {0.07f, 0.06f, 0.06f};
    case Medium::Chalk: return {0.95f, 0.95f, 0.9f};
    case Medium::Pencil: break;
  }
  return {0.16f, 0.16f, 0.19f};
}

}  // namespace

TexturedSketcher::TexturedSketcher(Medium medium)
    : medium_(medium), program_(Program::from_files({"sketch/textured.vert", "sketch/textured.frag"})),
      smudge_program_(Program::from_files({"sketch/smudge.vert", "sketch/smudge.frag"})) {}

std::vector<ParamSpec> TexturedSketcher::params(Medium medium) {
  std::vector<ParamSpec> specs = SketchEdgeSource::params(true);
  // Charcoal is the broadest medium, chalk next, pencil the finest.
  const char* min_width = medium == Medium::Charcoal ? "0.011" : medium == Medium::Chalk ? "0.008" : "0.005";
  const char* max_width = medium == Medium::Charcoal ? "0.028" : medium == Medium::Chalk ? "0.02" : "0.012";
  const std::vector<ParamSpec> own = {
      float_param("width", "0.15", 0, 4, "stroke width as a fraction of the edge's length..."),
      float_param("min_width", min_width, 0, 0.2, "...but at least this fraction of the bounding-box diagonal..."),
      float_param("max_width", max_width, 0, 0.2, "...and at most this"),
      float_param("texture_length", "0.08", 0.001, 10, "one repeat of the stroke texture, as a fraction of the diagonal"),
      float_param("strength", "1", 0, 1, "how hard the medium is pressed (opacity)"),
      int_param("variants", "4", 1, 16, "stroke textures to choose from"),
      // Charcoal is pressed unevenly, catches the paper and is rubbed; pencil and chalk keep
      // their look unless asked.
      float_param("pressure", medium == Medium::Charcoal ? "0.8" : "0", 0, 1,
                  "how much the pressure varies along a stroke (its width and darkness)"),
      float_param("grain", medium == Medium::Charcoal ? "0.75" : "0", 0, 1, "how much the paper's tooth breaks the strokes"),
      float_param("smudge", medium == Medium::Charcoal ? "0.6" : "0", 0, 1, "a rubbed tone along the outline on the shadow side"),
  };
  specs.insert(specs.end(), own.begin(), own.end());
  return specs;
}

void TexturedSketcher::configure(const StyleParams& p) {
  edges_.configure(p);
  width_ratio_ = p.get_float("width");
  min_width_ratio_ = p.get_float("min_width");
  max_width_ratio_ = std::max(p.get_float("max_width"), min_width_ratio_);
  texture_length_ratio_ = p.get_float("texture_length");
  strength_ = p.get_float("strength");
  pressure_ = p.get_float("pressure");
  grain_ = p.get_float("grain");
  smudge_ = p.get_float("smudge");
  const int variants = p.get_int("variants");
  if (variants != variants_ && textures_) textures_.reset();
  variants_ = variants;
  if (object_) prepare(*object_);
}

void TexturedSketcher::prepare(const SceneObject& object) {
  const bool new_object = object_ != &object;
  object_ = &object;
  edges_.prepare(object);
  if (new_object || !mesh_) mesh_ = std::make_unique<GpuMesh>(object);
  if (!textures_) textures_ = std::make_unique<Texture>(Texture::stack_from_images(make_stroke_textures(medium_, variants_), GL_TEXTURE_2D_ARRAY,
                                                                                  {.repeat = true, .clamp_t = true, .mipmaps = true, .linear = true}));
  const float diagonal = object.topology.bounds.diagonal();
  // Pressure per vertex, so two edges meeting at one press alike there and it changes smoothly
  // along the outline instead of per edge.
  pressures_.resize(object.mesh.positions.size());
  const float cells = 1.0f / std::max(kPressurePeriod * diagonal, 1e-9f);
  for (size_t i = 0; i < pressures_.size(); ++i) {
    const glm::vec3 q = object.mesh.positions[i] * cells;
    // Value noise gathers about 0.5; a hand presses hard or lightly, so spread it out.
    const float p = value_noise(q.x, q.y, q.z, 17);
    pressures_[i] = std::clamp((p - 0.5f) * 2.0f + 0.5f, 0.0f, 1.0f);
  }
  min_width_ = min_width_ratio_ * diagonal;
  max_width_ = max_width_ratio_ * diagonal;
  // A look per edge for life: seeded by the edge's index, so it never changes between frames.
  const float texture_length = texture_length_ratio_ * diagonal;
  looks_.resize(object.topology.edges.size());
  for (size_t i = 0; i < looks_.size(); ++i) {
    StrokeRandom random(stroke_seed(i, 41));
    looks_[i] = {float(random.next() % uint64_t(variants_)), random.uniform(0.0f, 1.0f),
                 object.topology.edges[i].length / texture_length};
  }
  // Quads: corners 4i..4i+3 as two triangles; enough for every edge at once.
  std::vector<uint32_t> indices;
  indices.reserve(looks_.size() * 6);
  for (uint32_t q = 0; q < looks_.size(); ++q)
    for (uint32_t c : {0u, 1u, 2u, 2u, 1u, 3u}) indices.push_back(4 * q + c);
  quad_indices_ = Buffer::create_indices(indices);
  vertices_ = Buffer::create(0, nullptr, GL_STREAM_DRAW);
  vao_ = VertexArray::create();
  vao_.attribute(0, vertices_, 3, sizeof(Vertex), offsetof(Vertex, position));
  vao_.attribute(1, vertices_, 3, sizeof(Vertex), offsetof(Vertex, coord));
  vao_.attribute(2, vertices_, 1, sizeof(Vertex), offsetof(Vertex, opacity));
  vao_.attribute(3, vertices_, 2, sizeof(Vertex), offsetof(Vertex, run));
  vao_.attribute(4, vertices_, 1, sizeof(Vertex), offsetof(Vertex, pressure));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, quad_indices_.id());  // recorded in vao_
  glBindVertexArray(0);
}

void TexturedSketcher::draw(const FrameState& frame) {
  if (!mesh_) throw Error("TexturedSketcher::draw(): prepare() was not called");
  const Mesh& mesh = object_->mesh;
  const glm::vec3 eye = frame.eye_in_object_space();
  quads_.clear();
  for (const DrawnEdge& d : edges_.choose(eye)) {
    const Edge& e = object_->topology.edges[d.edge];
    const glm::vec3 a = mesh.positions[e.v0], b = mesh.positions[e.v1];
    // Widen across the edge and the view: cross(E, V).
    glm::vec3 across = glm::cross(b - a, 0.5f * (a + b) - eye);
    const float l = glm::length(across);
    if (l <= 1e-12f) continue;  // edge seen end-on
    const float half = 0.5f * std::clamp(e.length * width_ratio_, min_width_, max_width_);
    across /= l;
    // Pressure widens and darkens the stroke where it is high, thins and lightens it where low.
    const float pa = pressures_[e.v0], pb = pressures_[e.v1];
    auto width_at = [&](float p) { return half * (1.0f + 1.2f * pressure_ * (p - 0.5f)); };
    auto darkness_at = [&](float p) { return std::clamp(1.0f + 1.5f * pressure_ * (p - 0.5f), 0.2f, 1.0f); };
    // Run on past both ends by half the width, so strokes meeting at a vertex overlap instead
    // of leaving notches where the outline turns.
    const glm::vec3 along = (b - a) * (half / std::max(e.length, 1e-12f));
    const EdgeLook& look = looks_[d.edge];
    const float overrun = look.u_repeat * half / std::max(e.length, 1e-12f);
    const float u0 = look.u_start - overrun, u1 = look.u_start + look.u_repeat + overrun;
    // The ends fade over the overrun, so overlapping strokes blend rather than stack blocks.
    const float run = e.length / half + 2.0f;
    const float oa = d.opacity * darkness_at(pa), ob = d.opacity * darkness_at(pb);
    quads_.push_back({a - along - across * width_at(pa), {u0, 0.0f, look.variant}, oa, {0.0f, run}, pa});
    quads_.push_back({a - along + across * width_at(pa), {u0, 1.0f, look.variant}, oa, {0.0f, run}, pa});
    quads_.push_back({b + along - across * width_at(pb), {u1, 0.0f, look.variant}, ob, {run, run}, pb});
    quads_.push_back({b + along + across * width_at(pb), {u1, 1.0f, look.variant}, ob, {run, run}, pb});
  }
  vertices_.upload(quads_.size() * sizeof(Vertex), quads_.data());

  const glm::mat4 mvp = frame.model_view_projection();
  hlr_.lay_depth(*mesh_, frame);
  HiddenLineRemoval::begin_lines();  // depth test on, writes off
  const glm::vec2 tooth_size{float(kToothSize), float(kToothSize)};
  const bool dry = grain_ > 0.0f || smudge_ > 0.0f;
  if (dry && !tooth_) tooth_ = std::make_unique<Texture>(Texture::from_image(paper_tooth(kToothSize), {.repeat = true, .mipmaps = false, .linear = false}));
  if (smudge_ > 0.0f) {
    // Under the strokes: the rubbed tone lies on the surface, the lines over it.
    smudge_program_.use();
    smudge_program_.set("model_view_projection", mvp);
    smudge_program_.set("eye_object", eye);
    smudge_program_.set("light_object", frame.light_in_object_space());
    smudge_program_.set("smudge", smudge_ * strength_);
    smudge_program_.set("ink_colour", ink_of(medium_));
    smudge_program_.set("tooth", 1);
    smudge_program_.set("tooth_size", tooth_size);
    tooth_->bind(1);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    mesh_->bind();
    mesh_->draw_all();
    glDisable(GL_CULL_FACE);
  }
  program_.use();
  program_.set("model_view_projection", mvp);
  program_.set("depth_bias", depth_bias_);
  program_.set("strength", strength_);
  program_.set("strokes", 0);
  program_.set("grain", grain_);
  program_.set("tooth", 1);
  program_.set("tooth_size", tooth_size);
  textures_->bind(0);
  if (dry) tooth_->bind(1);
  vao_.bind();
  glDrawElements(GL_TRIANGLES, GLsizei(quads_.size() / 4 * 6), GL_UNSIGNED_INT, nullptr);
  HiddenLineRemoval::end_lines();
}

std::map<std::string, double> TexturedSketcher::counters() const { return edges_.counters(); }

}  // namespace inkwire
