#include "client/render/tween/tween_renderer.hpp"

#include <algorithm>
#include <cmath>

#include <glm/trigonometric.hpp>

#include "client/render/tween/mesh_samples.hpp"
#include "common/camera.hpp"
#include "common/error.hpp"
#include "common/tween/view_sphere.hpp"

namespace inkwire {

void validate(const TweenModel& m, bool partial) {
  if (m.images.size() != size_t(m.data.sample_count()) && !(partial && m.images.empty()))
    throw Error("tween model: " + std::to_string(m.images.size()) + " images for " + std::to_string(m.data.sample_count()) + " samples");
  if (m.data.width < 1 || m.data.height < 1 || m.data.width > kMaxTweenImageSide || m.data.height > kMaxTweenImageSide)
    throw Error("tween model: image size " + std::to_string(m.data.width) + "x" + std::to_string(m.data.height) + " is not allowed");
  for (size_t i = 0; i < m.images.size(); ++i)
    if (!(partial && m.images[i].empty()) && (m.images[i].width != m.data.width || m.images[i].height != m.data.height))
      throw Error("tween model: sample " + std::to_string(i) + " is " + std::to_string(m.images[i].width) + "x" +
                  std::to_string(m.images[i].height) + ", the tween data says " + std::to_string(m.data.width) + "x" +
                  std::to_string(m.data.height));
  if (m.data.cells.empty() && !partial) throw Error("tween model: no cells");
}

std::vector<ParamSpec> TweenRenderer::params() {
  return {
      choice_param("method", "bilinear", {"nearest", "crossfade", "linear", "bilinear", "trilinear"},
                   "how a view is made from the samples around it (trilinear samples a geodesic sphere, the others a ring)"),
      choice_param("passes", "one", {"one", "per-sample"},
                   "one pass reading every sample, or the study's one pass per sample summed in an off-screen view"),
      choice_param("overlap", "layered", {"layered", "depth-clear"},
                   "per-sample passes: how folded triangles are kept from adding up (passes laid nearer and nearer, or depth cleared per pass)"),
      choice_param("layout", "auto", {"auto", "ring", "sphere"},
                   "where samples are taken: a ring on the equator or a geodesic sphere (auto: sphere for trilinear only)"),
      int_param("samples", "24", 3, 360, "samples on the ring (24 = every 15 degrees)"),
      int_param("sphere_level", "2", 0, 3, "geodesic sphere subdivisions for trilinear (0: 12 samples, 1: 42, 2: 162)"),
      int_param("points", "65", 3, 2000, "control points per sample pair or triangle"),
      int_param("sample_size", "256", 32, 2048, "sample images are this many pixels square"),
      text_param("sample_style", "default", "the style the samples are rendered in", {"default", "comic", "comic-extended", "hidden-line", "hatching"}),
      choice_param("compose", "matte", {"matte", "sum"},
                   "matte: one outline where the warped samples' mattes agree (no ghosted edge); sum: the plain weighted sum"),
  };
}

void TweenRenderer::configure(const StyleParams& p) {
  method_ = p.get_text("method");
  one_pass_ = p.get_text("passes") == "one";
  overlap_ = p.get_text("overlap") == "depth-clear" ? OverlapMode::DepthClear : OverlapMode::Layered;
  layout_ = p.get_text("layout");
  ring_samples_ = p.get_int("samples");
  sphere_level_ = p.get_int("sphere_level");
  points_ = p.get_int("points");
  sample_size_ = p.get_int("sample_size");
  sample_style_ = p.get_text("sample_style");
  // Per-sample passes are the study's additive sum; composing by mattes reads every sample at once.
  const bool matte = p.get_text("compose") == "matte" && one_pass_;
  if (matte != matte_ && warper_) {
    matte_ = matte;
    warper_->set_matte(matte_);
    // The textures follow the compose mode (matte samples carry distances, not alpha).
    for (size_t i = 0; i < model_.images.size() && i < textures_.size(); ++i)
      if (textures_[i]) set_sample(int(i), model_.images[i]);
    for (auto& [index, finer] : finer_) set_finer_sample(index, finer.image);
  }
  matte_ = matte;
  if (sample_style_ == "tween") throw Error("sample_style cannot be tween itself");
}

void TweenRenderer::prepare(const SceneObject& object) {
  object_ = &object;
  built_for_.clear();
  build_from_mesh();
}

void TweenRenderer::build_from_mesh() {
  const bool sphere = layout_ == "sphere" || (layout_ == "auto" && method_ == "trilinear");
  const std::string sampling = (sphere ? "sphere" + std::to_string(sphere_level_) : "ring" + std::to_string(ring_samples_)) +
                               "/" + std::to_string(points_) + "/" + std::to_string(sample_size_) + "/" + sample_style_;
  if (sampling == built_for_) return;
  std::vector<glm::vec3> directions;
  std::vector<std::vector<uint16_t>> cells;
  if (sphere) {
    ViewSphere s = geodesic_sphere(sphere_level_);
    directions = std::move(s.directions);
    cells = std::move(s.triangles);
  } else {
    directions = ring_directions(ring_samples_);
    cells = ring_cells(ring_samples_);
  }
  TweenModel m;
  m.distance_diagonals = 1.4f;
  const MeshSamples samples = render_mesh_samples(*object_, directions, sample_size_, m.distance_diagonals, sample_style_);
  m.data = exact_tween_data(samples, *object_, cells, points_);
  for (const Image& image : samples.images) m.images.push_back(without_floor(image));
  m.bounds = object_->topology.bounds;
  model_ = std::move(m);
  built_for_ = sampling;
  upload();
}

void TweenRenderer::use_model(TweenModel model) {
  validate(model);
  model_ = std::move(model);
  object_ = nullptr;
  built_for_.clear();
  upload();
}

void TweenRenderer::begin_model(TweenModel model) {
  validate(model, true);
  if (model.images.empty()) model.images.resize(size_t(model.data.sample_count()));
  model_ = std::move(model);
  object_ = nullptr;
  built_for_.clear();
  upload();
}

void TweenRenderer::set_sample(int index, const Image& image) {
  if (index < 0 || index >= model_.data.sample_count()) throw Error("tween: sample " + std::to_string(index) + " is not in the model");
  if (image.width != model_.data.width || image.height != model_.data.height)
    throw Error("tween: sample " + std::to_string(index) + " is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                ", not " + std::to_string(model_.data.width) + "x" + std::to_string(model_.data.height));
  if (&model_.images[size_t(index)] != &image) model_.images[size_t(index)] = image;
  last_view_ = {};  // it may point at the texture about to go
  textures_[size_t(index)] = std::make_unique<gl::Texture>(matte_ ? make_matte_texture(image) : make_sample_texture(image));
}

void TweenRenderer::set_finer_sample(int index, const Image& image) {
  if (index < 0 || index >= model_.data.sample_count()) throw Error("tween: sample " + std::to_string(index) + " is not in the model");
  const float scale = float(image.height) / float(model_.data.height);
  const float aspect = float(image.width) / float(image.height), own = float(model_.data.width) / float(model_.data.height);
  if (scale <= 1.0f || std::abs(aspect / own - 1.0f) > 0.01f)
    throw Error("tween: a finer level of sample " + std::to_string(index) + " is " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + ", not larger than " + std::to_string(model_.data.width) + "x" +
                std::to_string(model_.data.height) + " and of its shape");
  last_view_ = {};  // it may point at the texture about to go
  Finer& finer = finer_[index];
  if (&finer.image != &image) finer.image = image;
  finer.scale = scale;
  // Its matte texture from the ratio in double precision, as the browser's (the same bytes).
  finer.texture = std::make_unique<gl::Texture>(matte_ ? make_matte_texture(image, double(image.height) / double(model_.data.height)) : make_sample_texture(image));
}

void TweenRenderer::drop_finer_sample(int index) {
  last_view_ = {};
  finer_.erase(index);
}

int TweenRenderer::finer_in_view() const {
  return int(std::count_if(last_view_.sources.begin(), last_view_.sources.end(), [](const WarpSource& w) { return w.scale > 1.0f; }));
}

std::vector<int> TweenRenderer::view_samples(const glm::vec3& direction) const { return inkwire::view_samples(model_.data, direction); }

WarpSource TweenRenderer::source_of(int index, int position, float weight) const {
  if (use_finer_)
    if (const auto it = finer_.find(index); it != finer_.end()) return {it->second.texture.get(), position, weight, it->second.scale};
  return {textures_[size_t(index)].get(), position, weight};
}

void TweenRenderer::add_cell(TweenCell cell) {
  for (uint16_t s : cell.samples)
    if (s >= model_.data.sample_count()) throw Error("tween: a cell names sample " + std::to_string(s) + " of " + std::to_string(model_.data.sample_count()));
  add_cell_mesh(cell);
  model_.data.cells.push_back(std::move(cell));
}

int TweenRenderer::samples_loaded() const {
  return int(std::count_if(textures_.begin(), textures_.end(), [](const auto& t) { return t != nullptr; }));
}

void TweenRenderer::add_cell_mesh(const TweenCell& cell) {
  meshes_.push_back(warper_->add_mesh(build_warp_mesh(cell, model_.data.width, model_.data.height)));
}

void TweenRenderer::upload() {
  last_view_ = {};  // it points into the textures about to go
  warper_ = std::make_unique<ImageWarper>(model_.data.width, model_.data.height);
  warper_->set_matte(matte_);
  textures_.clear();
  textures_.resize(model_.images.size());
  finer_.clear();
  for (size_t i = 0; i < model_.images.size(); ++i)
    if (!model_.images[i].empty()) set_sample(int(i), model_.images[i]);
  meshes_.clear();
  for (const TweenCell& cell : model_.data.cells) add_cell_mesh(cell);
  plain_mesh_ = warper_->add_mesh(build_warp_mesh(TweenCell{.samples = {0, 1}, .points = {}}, model_.data.width, model_.data.height));
}

TweenRenderer::View TweenRenderer::nearest_loaded(const glm::vec3& direction) {
  View view;
  const int i = nearest_sample(model_.data.directions, direction, [&](int s) { return textures_[size_t(s)] != nullptr; });
  if (i < 0) return view;
  view.mesh = plain_mesh_;
  view.positions = {1.0f, 0.0f, 0.0f};
  view.sources = {source_of(i, 0, 1.0f)};
  view.sample = i;
  return view;
}

TweenRenderer::View TweenRenderer::plan(const FrameState& frame) {
  const glm::vec3 direction = frame.eye_in_object_space() - model_.bounds.centre();
  const CellLocation at = locate_view(model_.data, direction);
  last_cell_ = at.cell;
  const View fallback = nearest_loaded(direction);
  if (at.cell < 0) return fallback;
  const TweenCell& cell = model_.data.cells[size_t(at.cell)];
  const bool pair = cell.is_pair();
  const int n = int(cell.samples.size());
  // Until every sample of the view's cell is there, the nearest sample that is there shows; so it
  // does outside every cell (past an open ring's end, above the top row), and for a pair that
  // does not hold the nearest sample (a view off a wobbling calibrated ring, located in a pair
  // beside its own: on templeRing 0.6 dB better than that pair's tween). Not for triangles:
  // between rows the nearest photo can be the quad's corner across the diagonal, outside the
  // triangle that holds the view.
  bool whole = true, holds_nearest = false;
  for (uint16_t s : cell.samples) {
    whole = whole && textures_[s] != nullptr;
    holds_nearest = holds_nearest || s == fallback.sample;
  }
  if (!whole || !at.inside || (cell.is_pair() && !holds_nearest)) {
    last_cell_ = -1;
    return fallback;
  }
  // Which stored position of a point belongs to the cell's k-th sample, and where the view puts it.
  auto slot = [&](int k) { return pair ? 2 * k : k; };
  auto source = [&](int k, int position, float weight) { return source_of(cell.samples[size_t(k)], position, weight); };
  auto own_positions = [&](int k) {
    glm::vec3 w(0.0f);
    w[slot(k)] = 1.0f;
    return w;
  };
  View view;
  view.mesh = meshes_[size_t(at.cell)];
  const glm::vec3 between = pair ? path_weights(at.t) : glm::vec3(at.weights[0], at.weights[1], at.weights[2]);
  int nearest = 0;
  for (int k = 1; k < n; ++k)
    if (at.weights[size_t(k)] > at.weights[size_t(nearest)]) nearest = k;
  if (method_ == "nearest") {
    view.positions = own_positions(nearest);
    view.sources = {source(nearest, slot(nearest), 1.0f)};
  } else if (method_ == "linear") {
    view.positions = between;
    view.sources = {source(nearest, slot(nearest), 1.0f)};
  } else if (method_ == "crossfade") {
    // Unwarped: the mesh drawn where it lies in the first sample, and every sample read at those
    // same pixels, i.e. each image as it is.
    view.positions = own_positions(0);
    for (int k = 0; k < n; ++k) view.sources.push_back(source(k, slot(0), at.weights[size_t(k)]));
  } else {  // bilinear on a ring pair, trilinear on a sphere triangle
    view.positions = between;
    for (int k = 0; k < n; ++k) view.sources.push_back(source(k, slot(k), at.weights[size_t(k)]));
  }
  return view;
}

void TweenRenderer::draw(const FrameState& frame) {
  if (object_) build_from_mesh();  // the method may have moved between ring and sphere
  if (!warper_) throw Error("tween: nothing to draw (no mesh prepared and no samples given)");
  last_view_ = plan(frame);
  last_passes_ = 0;
  if (last_view_.mesh < 0) return;

  // The samples were taken from model_.distance_diagonals away; nearer views see them larger.
  const glm::vec3 centre = model_.bounds.centre();
  const float diagonal = std::max(model_.bounds.diagonal(), 1e-6f);
  const float frame_distance = std::max(glm::length(frame.eye_in_object_space() - centre) / diagonal, 1e-3f);
  const float zoom = (model_.distance_diagonals / frame_distance) * std::tan(glm::radians(model_.fov_y_degrees) / 2.0f) /
                     std::tan(glm::radians(frame.camera.fov_y_degrees) / 2.0f);
  // The photos letterboxed: a viewport narrower than they are shows them whole (fit_scale).
  const float photo_aspect = float(model_.data.width) / float(model_.data.height);
  const float h = float(frame.viewport.y) * zoom * fit_scale(float(frame.viewport.x) / float(frame.viewport.y), photo_aspect);
  const float w = h * photo_aspect;
  const glm::vec4 rect((float(frame.viewport.x) - w) / 2.0f, (float(frame.viewport.y) - h) / 2.0f, w, h);

  if (one_pass_) {
    warper_->draw_over(last_view_.mesh, last_view_.positions, last_view_.sources, rect);
    last_passes_ = 1;
    return;
  }
  warper_->begin(overlap_);
  for (const WarpSource& s : last_view_.sources) {
    warper_->pass(last_view_.mesh, *s.image, last_view_.positions, s.position, s.weight, s.scale);
    ++last_passes_;
  }
  warper_->end();
  warper_->composite(rect);
}

std::map<std::string, double> TweenRenderer::counters() const {
  std::map<std::string, double> c;
  if (last_cell_ >= 0 && warper_) c["triangles"] = double(warper_->triangles(meshes_[size_t(last_cell_)]));
  c["passes"] = last_passes_;
  c["cell"] = last_cell_;
  c["samples_loaded"] = samples_loaded();
  // Zoom (SPEC T18): finer levels held, and how many of the last view's samples were drawn from one.
  c["finer_samples"] = double(finer_.size());
  c["finer_in_view"] = finer_in_view();
  // Measured when asked (rarely), not each time a cell arrives: the model's tween data as the
  // codec writes it, per cell.
  if (warper_ && !model_.data.cells.empty())
    c["bytes_per_cell"] = double(encode_tween(model_.data).size()) / double(model_.data.cells.size());
  return c;
}

Image TweenRenderer::last_view() const {
  if (!warper_) throw Error("tween: no view drawn yet");
  // One-pass views went straight into the frame: made again at the samples' resolution.
  if (one_pass_ && last_view_.mesh >= 0) warper_->render(last_view_.mesh, last_view_.positions, last_view_.sources);
  return warper_->read();
}

}  // namespace inkwire
