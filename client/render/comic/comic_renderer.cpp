#include "client/render/comic/comic_renderer.hpp"

#include <sstream>

#include "common/error.hpp"

namespace inkwire {

using namespace gl;

namespace {

std::vector<float> parse_floats(const std::string& text) {
  std::vector<float> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    try {
      size_t used = 0;
      values.push_back(std::stof(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw Error("band_edges '" + text + "' is not a comma-separated list of numbers");
    }
  }
  return values;
}

std::vector<std::string> shade_map_choices() { return shade_map_names(); }

}  // namespace

ComicRenderer::ComicRenderer(bool extended)
    : extended_(extended),
      fill_(Program::from_files({"comic/comic.vert", "comic/comic.frag"}, extended ? std::vector<std::string>{"EXTENDED 1"}
                                                                                    : std::vector<std::string>{})),
      outline_(Program::from_files({"comic/outline.vert", "comic/outline.frag"})) {}

std::vector<ParamSpec> ComicRenderer::params(bool extended) {
  return {
      choice_param("shade_map", "comic", shade_map_choices(), "generated shade map"),
      {"shade_file", ParamType::Text, "", "shade map image (x: N.L, up: R.V; 128 = own colour, 255 = white); overrides shade_map", 0, 0, {}},
      bool_param("shade_smooth", "false", "filter a loaded shade map linearly instead of keeping hard bands"),
      int_param("bands", "3", 1, 16, "diffuse bands of the 'comic', 'lines' and 'warm-cool' maps"),
      {"band_edges", ParamType::Text, "", "N.L where bands change, comma-separated (empty: equal bands)", 0, 0, {}},
      float_param("shadow", "0.24", 0, 1, "how much darker the darkest band is (studied cartoons: 0.24 +- 0.07)"),
      float_param("highlight", "0.7", 0, 1, "highlight band's lift toward white (extended)"),
      float_param("highlight_threshold", "0.96", 0, 1, "R.V where the highlight band starts, 0 = none (extended)"),
      float_param("shadow_saturation", "0.12", 0, 1, "saturation raised in shadow (studied cartoons: ~0.12)"),
      float_param("outline_width", "4", 0, 16, "outline width in pixels (inner lines come out about half), 0 = none"),
      colour_param("outline_colour", "#000000", "outline colour"),
      bool_param("coloured_outline", "false", "outline in the object's own colour, darkened"),
      float_param("outline_darkening", "0.6", 0, 1, "how much the coloured outline darkens the object colour"),
      choice_param("orientation", extended ? "vertex" : "gl", {"gl", "triangle", "triangle-corrected", "triangle-exact", "vertex"},
                   "how front faces are chosen: GL culling or the study's CPU methods"),
      int_param("k", "1", 1, 3, "vertex orientation: draw triangles with at least k front vertices"),
      bool_param("vertex_margin", "true",
                 "widen vertex thresholds so k=1 keeps every face the corrected triangle test keeps (false: the study's plain rule)"),
  };
}

void ComicRenderer::configure(const StyleParams& p) {
  const std::string orientation = p.get_text("orientation");
  orientation_.reset();
  if (orientation != "gl") orientation_ = parse_orientation(orientation);
  k_ = p.get_int("k");
  use_vertex_margins_ = p.get_bool("vertex_margin");
  outline_width_ = p.get_float("outline_width");
  ink_ = p.get_colour("outline_colour");
  coloured_outline_ = p.get_bool("coloured_outline");
  outline_darkening_ = p.get_float("outline_darkening");
  shadow_saturation_ = p.get_float("shadow_saturation");

  if (!p.get_text("shade_file").empty()) {
    shade_map_ = load_shade_map(p.get_text("shade_file"), p.get_bool("shade_smooth"));
  } else {
    ShadeMapOptions o;
    o.bands = p.get_int("bands");
    o.band_edges = parse_floats(p.get_text("band_edges"));
    o.shadow = p.get_float("shadow");
    o.highlight = p.get_float("highlight");
    o.highlight_threshold = extended_ ? p.get_float("highlight_threshold") : 0.0f;
    shade_map_ = make_shade_map(p.get_text("shade_map"), o);
  }
  shade_texture_.reset();  // rebuilt on the next draw, in the drawing context
}

void ComicRenderer::upload_shade_map() {
  const Image& img = shade_map_.image;
  if (extended_) {
    shade_texture_ = Texture::from_image(img, {.repeat = false, .mipmaps = false, .linear = shade_map_.smooth});
  } else {
    // The standard renderer's 1D map is the map's R.V = 0 row: the image's bottom row.
    std::vector<glm::u8vec4> row(size_t(img.width));
    for (int x = 0; x < img.width; ++x) row[size_t(x)] = img.rgba(x, img.height - 1);
    shade_texture_ = Texture::lookup_1d(row, shade_map_.smooth);
  }
}

void ComicRenderer::prepare(const SceneObject& object) {
  object_ = &object;
  mesh_ = std::make_unique<GpuMesh>(object);
  vertex_margins_ = vertex_margins(object.mesh, object.topology);
  triangle_colours_ = Buffer::create(mesh_->flat_colours());
  drawn_slots_ = Buffer::create(mesh_->triangle_source().size() * sizeof(uint32_t), nullptr, GL_STREAM_DRAW);
  dynamic_elements_ = Buffer::create(mesh_->indices().size() * sizeof(uint32_t), nullptr, GL_STREAM_DRAW);
  dynamic_vao_ = mesh_->vertex_array_with(dynamic_elements_);
}

void ComicRenderer::pick_triangles() {
  const ViewSetup view = ViewSetup::from(object_->topology, last_eye_);
  triangles_drawn_ = orient_triangles(*orientation_, k_, object_->mesh, object_->topology, view, draw_flags_, vertex_scratch_,
                                     use_vertex_margins_ ? &vertex_margins_ : nullptr);
  const auto& source = mesh_->triangle_source();
  const auto& indices = mesh_->indices();
  picked_indices_.clear();
  picked_slots_.clear();
  picked_ranges_.clear();
  for (const GpuBatch& batch : mesh_->batches()) {
    const uint32_t first = uint32_t(picked_slots_.size());
    for (uint32_t slot = batch.first_index / 3, end = slot + batch.index_count / 3; slot < end; ++slot) {
      if (!draw_flags_[source[slot]]) continue;
      picked_indices_.insert(picked_indices_.end(), &indices[3 * slot], &indices[3 * slot] + 3);
      picked_slots_.push_back(slot);
    }
    picked_ranges_.push_back({first, uint32_t(picked_slots_.size()) - first});
  }
  dynamic_elements_.upload(picked_indices_.size() * sizeof(uint32_t), picked_indices_.data());
  drawn_slots_.upload(picked_slots_.size() * sizeof(uint32_t), picked_slots_.data());
}

void ComicRenderer::draw_fill(const FrameState& frame) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  fill_.use();
  fill_.set("model_view_projection", frame.model_view_projection());
  const glm::vec3 light = frame.light_in_object_space();
  const ViewSetup view = ViewSetup::from(object_->topology, last_eye_);
  fill_.set("light_object", light);
  fill_.set("view_object", view.view);
  fill_.set("eye_object", last_eye_);
  fill_.set("exact_view", int(orientation_ == Orientation::TriangleExact));
  fill_.set("light_dot_view", glm::dot(light, view.view));
  fill_.set("shadow_saturation", shadow_saturation_);
  fill_.set("shade_map", 1);
  fill_.set("base_texture", 0);
  shade_texture_->bind(1);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, triangle_colours_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, drawn_slots_.id());

  const auto& batches = mesh_->batches();
  if (orientation_) {
    glDisable(GL_CULL_FACE);  // the orientation method has already chosen the faces
    fill_.set("remapped", 1);
    dynamic_vao_.bind();
    for (size_t b = 0; b < batches.size(); ++b) {
      const Range& r = picked_ranges_[b];
      if (r.triangles == 0) continue;
      fill_.set("textured", int(batches[b].textured));
      fill_.set("first_primitive", int(r.first_triangle));
      mesh_->bind_texture(batches[b], 0);
      glDrawElements(GL_TRIANGLES, GLsizei(r.triangles * 3), GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(size_t(r.first_triangle) * 3 * sizeof(uint32_t)));
    }
  } else {
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    fill_.set("remapped", 0);
    mesh_->bind();
    for (const GpuBatch& batch : batches) {
      fill_.set("textured", int(batch.textured));
      fill_.set("first_primitive", int(batch.first_index / 3));
      mesh_->draw(batch, 0);
    }
  }
}

void ComicRenderer::draw_outline(const FrameState& frame) {
  // Back faces as wide lines: the depth buffer hides their inner parts, leaving a thick
  // outline at the silhouette and thinner lines along creases.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  glDepthFunc(GL_LEQUAL);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glLineWidth(outline_width_);
  outline_.use();
  outline_.set("model_view_projection", frame.model_view_projection());
  outline_.set("coloured", int(coloured_outline_));
  outline_.set("darkening", outline_darkening_);
  outline_.set("ink", ink_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, triangle_colours_.id());
  mesh_->bind();
  mesh_->draw_all();
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glLineWidth(1.0f);
  glCullFace(GL_BACK);
  glDepthFunc(GL_LESS);
}

void ComicRenderer::draw(const FrameState& frame) {
  if (!mesh_) throw Error("ComicRenderer::draw(): prepare() was not called");
  if (!shade_texture_) upload_shade_map();
  last_eye_ = frame.eye_in_object_space();
  if (orientation_) pick_triangles();
  draw_fill(frame);
  if (outline_width_ > 0.0f) draw_outline(frame);
}

std::map<std::string, double> ComicRenderer::counters() const {
  if (!object_) return {};
  double front = double(triangles_drawn_);
  if (!orientation_) {  // GL culls: count what it keeps with the exact test it applies
    std::vector<uint8_t> flags;
    front = double(classify_faces(object_->mesh, object_->topology, last_eye_, flags));
  }
  return {{"front_faces", front}};
}

}  // namespace inkwire
