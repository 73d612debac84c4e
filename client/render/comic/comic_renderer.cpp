#include "client/render/comic/comic_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/trigonometric.hpp>

#include "client/render/hidden_lines.hpp"
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

Program fill_program(bool extended, bool textured) {
  std::vector<std::string> defines;
  if (extended) defines.push_back("EXTENDED 1");
  if (textured) defines.push_back("TEXTURED 1");
  return Program::from_files({"comic/comic.vert", "comic/comic.frag"}, defines);
}

}  // namespace

ComicRenderer::ComicRenderer(bool extended)
    : extended_(extended),
      fill_{fill_program(extended, false), fill_program(extended, true)},
      backface_outline_(Program::from_files({"comic/outline.vert", "comic/outline.frag"})),
      edge_outline_(Program::from_files({"comic/edges.vert", "comic/edges.frag"})) {}

std::vector<ParamSpec> ComicRenderer::params(bool extended) {
  return {
      choice_param("shade_map", "comic", shade_map_names(), "generated shade map"),
      file_param("shade_file", "", "shade map image (x: N.L, up: R.V; 128 = own colour, 255 = white); overrides shade_map"),
      bool_param("shade_smooth", "false", "filter a loaded shade map linearly instead of keeping hard bands"),
      int_param("bands", "3", 1, 16, "diffuse bands of the 'comic', 'lines' and 'warm-cool' maps"),
      text_param("band_edges", "", "N.L where bands change, comma-separated (empty: equal bands)"),
      float_param("shadow", "0.24", 0, 1, "how much darker the darkest band is (studied cartoons: 0.24 +- 0.07)"),
      float_param("highlight", "0.7", 0, 1, "highlight band's lift toward white (extended)"),
      float_param("highlight_threshold", "0.96", 0, 1, "R.V where the highlight band starts, 0 = none (extended)"),
      float_param("shadow_saturation", "0.12", 0, 1, "saturation raised in shadow (studied cartoons: ~0.12)"),
      choice_param("outline", "edges", {"edges", "backfaces"},
                   "edges: silhouette and creases as lines; backfaces: every back face as a wide line (the study's method)"),
      float_param("outline_width", "4", 0, 16, "silhouette width in pixels; crease lines are half as wide; 0 = none"),
      float_param("crease_degrees", "60", 0, 180, "edges outline: draw creases sharper than this"),
      float_param("outline_tolerance", "0.5", 0, 4,
                  "edges outline: pixels a joined silhouette may be straightened by (0 = every edge as is)"),
      float_param("outline_min_length", "2", 0, 50, "edges outline: leave out joined lines shorter than this on screen, in pixels"),
      float_param("outline_error", "0.5", 0, 10,
                  "edges outline: find silhouettes on the coarsest level of detail straying less than this many pixels (0 = full mesh)"),
      colour_param("outline_colour", "#000000", "outline colour"),
      bool_param("coloured_outline", "false", "outline in the object's own colour, darkened"),
      float_param("outline_darkening", "0.6", 0, 1, "how much the coloured outline darkens the object colour"),
      choice_param("orientation", extended ? "vertex" : "gl", {"gl", "triangle", "triangle-corrected", "triangle-exact", "vertex"},
                   "how front faces are chosen: GL culling or the study's CPU methods"),
      int_param("k", "1", 1, 3, "vertex orientation: draw triangles with at least k front vertices"),
      bool_param("vertex_margin", "true",
                 "make k=1 keep every face the corrected triangle test keeps (false: the study's plain rule)"),
  };
}

void ComicRenderer::configure(const StyleParams& p) {
  const std::string orientation = p.get_text("orientation");
  orientation_.reset();
  if (orientation != "gl") orientation_ = parse_orientation(orientation);
  k_ = p.get_int("k");
  use_vertex_margins_ = p.get_bool("vertex_margin");
  backface_outline_mode_ = p.get_text("outline") == "backfaces";
  outline_width_ = p.get_float("outline_width");
  crease_radians_ = glm::radians(p.get_float("crease_degrees"));
  outline_tolerance_ = p.get_float("outline_tolerance");
  outline_min_length_ = p.get_float("outline_min_length");
  outline_error_ = p.get_float("outline_error");
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
    shade_texture_ = Texture::lookup_row(row, shade_map_.smooth);
  }
}

void ComicRenderer::prepare(const SceneObject& object) {
  object_ = &object;
  mesh_ = std::make_unique<GpuMesh>(object);
  vertex_margins_ = vertex_margins(object.mesh, object.topology);
  outline_levels_ = std::make_unique<MeshLevels>(object.mesh, object.topology);
  level_face_colours_.clear();
  for (size_t l = 0; l < outline_levels_->size(); ++l) {
    const Mesh& level = (*outline_levels_)[l].mesh;
    level_face_colours_.emplace_back(level.face_count());
    for (size_t t = 0; t < level.face_count(); ++t) level_face_colours_.back()[t] = flat_colour(level, t);
  }
  dynamic_elements_ = Buffer::create_indices(mesh_->indices().size() * sizeof(uint32_t), nullptr, GL_STREAM_DRAW);
  dynamic_vao_ = mesh_->vertex_array_with(dynamic_elements_);
  edge_vertices_ = Buffer::create(0, nullptr, GL_STREAM_DRAW);
  edge_vao_ = VertexArray::create();
  wide_line_attributes(edge_vao_, edge_vertices_, sizeof(LineVertex));
  edge_vao_.attribute(4, edge_vertices_, 3, sizeof(LineVertex), offsetof(LineVertex, colour));
  // Every edge once, with the faces beside it: the back-face outline draws those with a face
  // turned away.
  std::vector<BackfaceEdgeVertex> backface_edges;
  const Mesh& mesh = object.mesh;
  const Topology& topology = object.topology;
  backface_edges.reserve(6 * topology.edges.size());
  for (const Edge& e : topology.edges) {
    const uint32_t f1 = e.boundary ? e.f0 : e.f1;
    const glm::vec3 a = mesh.positions[e.v0], b = mesh.positions[e.v1];
    append_wide_line_corners(backface_edges, [&](bool at_a, float corner) {
      return BackfaceEdgeVertex{{at_a ? a : b, at_a ? b : a, corner, 1.0f}, topology.face_normals[e.f0], topology.face_normals[f1],
                                flat_colour(mesh, e.f0), flat_colour(mesh, f1)};
    });
  }
  backface_edge_vertices_ = backface_edges.size();
  backface_edges_ = Buffer::create(backface_edges);
  backface_vao_ = VertexArray::create();
  wide_line_attributes(backface_vao_, backface_edges_, sizeof(BackfaceEdgeVertex));
  backface_vao_.attribute(4, backface_edges_, 3, sizeof(BackfaceEdgeVertex), offsetof(BackfaceEdgeVertex, normal_a));
  backface_vao_.attribute(5, backface_edges_, 3, sizeof(BackfaceEdgeVertex), offsetof(BackfaceEdgeVertex, normal_b));
  backface_vao_.attribute(6, backface_edges_, 4, sizeof(BackfaceEdgeVertex), offsetof(BackfaceEdgeVertex, colour_a));
  backface_vao_.attribute(7, backface_edges_, 4, sizeof(BackfaceEdgeVertex), offsetof(BackfaceEdgeVertex, colour_b));
  glBindVertexArray(0);
}

void ComicRenderer::pick_triangles() {
  triangles_drawn_ = orient_triangles(*orientation_, k_, object_->mesh, object_->topology, view_, draw_flags_, vertex_scratch_,
                                     use_vertex_margins_ ? &vertex_margins_ : nullptr);
  const auto& source = mesh_->triangle_source();
  const uint32_t* indices = mesh_->indices().data();
  picked_indices_.resize(mesh_->indices().size());
  uint32_t* out = picked_indices_.data();
  picked_ranges_.clear();
  for (const GpuBatch& batch : mesh_->batches()) {
    const uint32_t first = uint32_t(out - picked_indices_.data()) / 3;
    for (uint32_t slot = batch.first_index / 3, end = slot + batch.index_count / 3; slot < end; ++slot)
      if (draw_flags_[source[slot]]) {
        out[0] = indices[3 * slot], out[1] = indices[3 * slot + 1], out[2] = indices[3 * slot + 2];
        out += 3;
      }
    picked_ranges_.push_back({first, uint32_t(out - picked_indices_.data()) / 3 - first});
  }
  picked_indices_.resize(size_t(out - picked_indices_.data()));
  dynamic_elements_.upload(picked_indices_.size() * sizeof(uint32_t), picked_indices_.data());
}

void ComicRenderer::draw_fill(const FrameState& frame) {
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  // GL culling stays on behind the CPU methods: they decide what is submitted (and lit);
  // culling never adds a hole, and keeps back faces a conservative method lets through
  // from being rasterised.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  // Push the fill back a little so outline lines lying on the surface win the depth test.
  // The offset's slope term can push nearly edge-on slivers at the silhouette past the far
  // end of the depth range, where they clamp to 1.0: LEQUAL still lets them cover the clear.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 2.0f);
  glDepthFunc(GL_LEQUAL);
  const glm::vec3 light = frame.light_in_object_space();
  for (const Program& fill : fill_) {
    fill.use();
    fill.set("model_view_projection", frame.model_view_projection());
    fill.set("light_object", light);
    fill.set("view_object", view_.view);
    fill.set("eye_object", view_.eye);
    fill.set("exact_view", int(orientation_ == Orientation::TriangleExact));
    fill.set("light_dot_view", glm::dot(light, view_.view));
    fill.set("shadow_saturation", shadow_saturation_);
    fill.set("shade_map", 1);
    fill.set("base_texture", 0);
  }
  shade_texture_->bind(1);

  const auto& batches = mesh_->batches();
  if (orientation_) {
    dynamic_vao_.bind();
    for (size_t b = 0; b < batches.size(); ++b) {
      const Range& r = picked_ranges_[b];
      if (r.triangles == 0) continue;
      fill_[batches[b].textured].use();
      mesh_->bind_texture(batches[b], 0);
      glDrawElements(GL_TRIANGLES, GLsizei(r.triangles * 3), GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(size_t(r.first_triangle) * 3 * sizeof(uint32_t)));
    }
  } else {
    mesh_->bind();
    for (const GpuBatch& batch : batches) {
      fill_[batch.textured].use();
      mesh_->draw(batch, 0);
    }
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthFunc(GL_LESS);
}

void ComicRenderer::draw_backface_outline(const FrameState& frame) {
  // Back faces' edges as wide lines (comic/outline.vert): the depth buffer hides their inner
  // parts, leaving a thick outline at the silhouette and thinner lines along creases.
  glDisable(GL_CULL_FACE);
  glDepthFunc(GL_LEQUAL);
  begin_smooth_lines();
  backface_outline_.use();
  backface_outline_.set("model_view_projection", frame.model_view_projection());
  backface_outline_.set("eye_object", view_.eye);
  backface_outline_.set("coloured", int(coloured_outline_));
  backface_outline_.set("darkening", outline_darkening_);
  backface_outline_.set("ink", ink_);
  set_wide_line_uniforms(backface_outline_, outline_width_);
  backface_vao_.bind();
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(backface_edge_vertices_));
  end_smooth_lines();
  glDepthFunc(GL_LESS);
}

void ComicRenderer::draw_edge_outline(const FrameState& frame) {
  // Pixels per object unit at the object's nearest possible point: how far a level's error
  // can show on screen.
  const Bounds& bounds = object_->topology.bounds;
  const float nearest = std::max(glm::length(view_.eye - bounds.centre()) - 0.5f * bounds.diagonal(), 1e-3f * bounds.diagonal());
  const float pixels_per_unit = float(frame.viewport.y) / (2.0f * std::tan(glm::radians(frame.camera.fov_y_degrees) * 0.5f) * nearest);
  const size_t level_index = outline_error_ > 0.0f ? outline_levels_->pick_index(pixels_per_unit, outline_error_) : 0;
  const MeshLevel& level = (*outline_levels_)[level_index];
  const std::vector<glm::vec4>& face_colours = level_face_colours_[level_index];
  outline_level_faces_ = level.mesh.face_count();
  const Mesh& mesh = level.mesh;
  const Topology& topology = level.topology;
  classify_faces(mesh, topology, view_.eye, exact_front_);
  // Silhouettes and open edges (group 0, full width) and creases seen from the front (group 1,
  // half width), each with the face whose colour a coloured outline takes.
  outline_edges_.clear();
  outline_faces_.clear();
  for (const Edge& e : topology.edges) {
    if (e.boundary || is_silhouette(e, exact_front_)) {
      outline_edges_.push_back({e.v0, e.v1, 0});
      outline_faces_.push_back(e.boundary || exact_front_[e.f0] ? e.f0 : e.f1);
    } else if (e.dihedral > crease_radians_ && exact_front_[e.f0]) {
      outline_edges_.push_back({e.v0, e.v1, 1});
      outline_faces_.push_back(e.f0);
    }
  }
  edges_drawn_ = outline_edges_.size();

  // Only the outline's vertices need projecting to pixels.
  const glm::mat4 mvp = frame.model_view_projection();
  const glm::vec2 half_viewport = 0.5f * glm::vec2(frame.viewport);
  screen_.resize(mesh.positions.size());
  for (const ChainEdge& e : outline_edges_)
    for (uint32_t v : {e.v0, e.v1}) {
      const glm::vec4 clip = mvp * glm::vec4(mesh.positions[v], 1.0f);
      screen_[v] = glm::vec2(clip) / std::max(clip.w, 1e-6f) * half_viewport;
    }

  for (auto& lines : line_vertices_) lines.clear();
  for (const Chain& chain : chains_.build(outline_edges_, mesh.positions.size())) {
    // Tiny closed loops and stubs (folds of a noisy surface) print as specks, not lines.
    float length = 0.0f;
    for (size_t i = 0; i + 1 < chain.vertices.size() && length < outline_min_length_; ++i)
      length += glm::length(screen_[chain.vertices[i + 1]] - screen_[chain.vertices[i]]);
    if (length < outline_min_length_) continue;
    simplify_chain(chain.vertices, screen_, outline_tolerance_, kept_);
    for (size_t i = 0; i + 1 < kept_.size(); ++i) {
      const uint32_t face = outline_faces_[chain.edges[kept_[i]]];
      const glm::vec3 c = coloured_outline_ ? glm::vec3(face_colours[face]) * (1.0f - outline_darkening_) : ink_;
      const glm::vec3 a = mesh.positions[chain.vertices[kept_[i]]], b = mesh.positions[chain.vertices[kept_[i + 1]]];
      append_wide_line_corners(line_vertices_[chain.group], [&](bool at_a, float corner) {
        return LineVertex{{at_a ? a : b, at_a ? b : a, corner, 1.0f}, c};
      });
    }
  }
  const size_t silhouette = line_vertices_[0].size();
  line_vertices_[0].insert(line_vertices_[0].end(), line_vertices_[1].begin(), line_vertices_[1].end());
  segments_drawn_ = line_vertices_[0].size() / 6;
  edge_vertices_.upload(line_vertices_[0].size() * sizeof(LineVertex), line_vertices_[0].data());

  glDisable(GL_CULL_FACE);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  edge_outline_.use();
  edge_outline_.set("model_view_projection", frame.model_view_projection());
  edge_vao_.bind();
  begin_smooth_lines();
  set_wide_line_uniforms(edge_outline_, outline_width_);
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(silhouette));
  set_wide_line_uniforms(edge_outline_, std::max(1.0f, 0.5f * outline_width_));
  glDrawArrays(GL_TRIANGLES, GLsizei(silhouette), GLsizei(line_vertices_[0].size() - silhouette));
  end_smooth_lines();
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

void ComicRenderer::draw(const FrameState& frame) {
  if (!mesh_) throw Error("ComicRenderer::draw(): prepare() was not called");
  if (!shade_texture_) upload_shade_map();
  view_ = ViewSetup::from(object_->topology, frame.eye_in_object_space());
  if (orientation_) pick_triangles();
  draw_fill(frame);
  if (outline_width_ <= 0.0f) return;
  if (backface_outline_mode_) draw_backface_outline(frame);
  else draw_edge_outline(frame);
}

std::map<std::string, double> ComicRenderer::counters() const {
  if (!object_) return {};
  double front = double(triangles_drawn_);
  if (!orientation_) {  // GL culls: count what it keeps with the exact test it applies
    std::vector<uint8_t> flags;
    front = double(classify_faces(object_->mesh, object_->topology, view_.eye, flags));
  }
  return {{"front_faces", front}, {"edges_drawn", double(edges_drawn_)}, {"outline_segments", double(segments_drawn_)},
          {"outline_level_faces", double(outline_level_faces_)}};
}

}  // namespace inkwire
