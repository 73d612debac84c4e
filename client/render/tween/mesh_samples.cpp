#include "client/render/tween/mesh_samples.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "client/gl/canvas.hpp"
#include "client/render/styles.hpp"
#include "common/tween/point_spread.hpp"
#include "common/tween/view_sphere.hpp"

namespace inkwire {

using namespace gl;
namespace {

// A vertex counts as visible when it is no deeper than the nearest surface around its pixel
// plus this fraction of the bounding-box diagonal (vertices on the silhouette see background).
constexpr float kVisibilitySlack = 0.01f;
// Share of the image side searched for the outline a vanished surface went through (24 pixels
// at 256: the same reach at every sample size).
constexpr float kOutlineReach = 0.094f;
// A hidden surface that faces a sample's camera by less than this many times the sine of the
// cell's span (the angle between its samples) is taken as turning out of sight, like one that
// faces away: a flank seen nearly edge-on, hidden behind the front's wider rim, has gone there
// through the outline, not behind the rim's middle.
constexpr float kGrazingSpans = 1.5f;

float eye_depth(const Camera& c, float window_depth) {
  const float z = 2.0f * window_depth - 1.0f;
  return 2.0f * c.near_plane * c.far_plane / (c.far_plane + c.near_plane - z * (c.far_plane - c.near_plane));
}

glm::mat4 view_projection(const Camera& c) { return c.projection(1.0f) * c.view(); }

Image draw_into(Renderer& renderer, Canvas& canvas, const Camera& camera) {
  canvas.bind();
  glClearColor(0, 0, 0, 0);
  glClearDepthf(1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  FrameState frame;
  frame.camera = camera;
  frame.viewport = canvas.size();
  frame.light_direction = default_light_direction(camera);
  renderer.draw(frame);
  return canvas.read();
}

// Colour from a multisampled canvas (smooth edges, like a photo); depth from a second,
// single-sampled drawing (multisampled depth cannot be read back). Made once per sample set.
struct SampleCanvases {
  explicit SampleCanvases(int size) : colour(size, size, 4), depth(size, size, 1) {}
  Canvas colour, depth;
};

Image draw_view(Renderer& renderer, SampleCanvases& canvases, const Camera& camera, std::vector<float>* depth) {
  Image image = draw_into(renderer, canvases.colour, camera);
  if (depth) {
    draw_into(renderer, canvases.depth, camera);
    *depth = canvases.depth.read_depth();
  }
  return image;
}

// Per sample of `cell` and per vertex, the cosine of the angle between the sample's camera and
// the vertex's most squarely facing face (-1 for a vertex on no face).
std::vector<std::vector<float>> facing_cosines(const MeshSamples& samples, const SceneObject& object, const std::vector<uint16_t>& cell) {
  std::vector<std::vector<float>> facing(cell.size(), std::vector<float>(object.mesh.positions.size(), -1.0f));
  for (size_t k = 0; k < cell.size(); ++k)
    for (size_t f = 0; f < object.mesh.triangles.size(); ++f) {
      const auto& t = object.mesh.triangles[f];
      const glm::vec3 centroid = (object.mesh.positions[t[0]] + object.mesh.positions[t[1]] + object.mesh.positions[t[2]]) / 3.0f;
      const float c = glm::dot(object.topology.face_normals[f], glm::normalize(samples.cameras[cell[k]].position - centroid));
      for (uint32_t i : t) facing[k][i] = std::max(facing[k][i], c);
    }
  return facing;
}

// The largest angle between two of the cell's sample directions (radians).
float cell_span(const MeshSamples& samples, const std::vector<uint16_t>& cell) {
  float span = 0.0f;
  for (size_t i = 0; i < cell.size(); ++i)
    for (size_t j = i + 1; j < cell.size(); ++j) {
      const float c = glm::dot(glm::normalize(samples.directions[cell[i]]), glm::normalize(samples.directions[cell[j]]));
      span = std::max(span, std::acos(std::clamp(c, -1.0f, 1.0f)));
    }
  return span;
}

}  // namespace

glm::vec3 MeshSamples::project(int index, const glm::vec3& point) const {
  const glm::vec4 clip = view_projection(cameras[size_t(index)]) * glm::vec4(point, 1.0f);
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * float(size), (0.5f - ndc.y * 0.5f) * float(size), ndc.z * 0.5f + 0.5f};
}

std::optional<glm::vec2> MeshSamples::position_in_front(int index, const glm::vec3& point, int reach) const {
  const glm::vec3 p = project(index, point);
  if (!(p.x >= 0.0f && p.y >= 0.0f && p.x < float(size) && p.y < float(size) && p.z > 0.0f && p.z < 1.0f)) return std::nullopt;
  const Camera& c = cameras[size_t(index)];
  const std::vector<float>& depth = depths[size_t(index)];
  const int px = int(p.x), py = int(p.y);
  float nearest = std::numeric_limits<float>::max();
  for (int y = std::max(0, py - reach); y <= std::min(size - 1, py + reach); ++y)
    for (int x = std::max(0, px - reach); x <= std::min(size - 1, px + reach); ++x)
      nearest = std::min(nearest, eye_depth(c, depth[size_t(y) * size + x]));
  if (eye_depth(c, p.z) > nearest + kVisibilitySlack * bounds.diagonal()) return std::nullopt;
  return glm::vec2(p);
}

std::optional<glm::vec2> MeshSamples::visible_position(int index, const glm::vec3& point) const {
  return position_in_front(index, point, 1);
}

std::optional<glm::vec2> MeshSamples::seen_position(int index, const glm::vec3& point) const {
  return position_in_front(index, point, 0);
}

std::optional<glm::vec2> MeshSamples::nearest_outline(int index, const glm::vec2& pixel, int reach) const {
  const std::vector<float>& depth = depths[size_t(index)];
  auto object_at = [&](int x, int y) { return x >= 0 && y >= 0 && x < size && y < size && depth[size_t(y) * size + x] < 1.0f; };
  std::optional<glm::vec2> best;
  float best_distance = std::numeric_limits<float>::max();
  const int px = int(pixel.x), py = int(pixel.y);
  for (int y = py - reach; y <= py + reach; ++y)
    for (int x = px - reach; x <= px + reach; ++x) {
      if (!object_at(x, y) || (object_at(x - 1, y) && object_at(x + 1, y) && object_at(x, y - 1) && object_at(x, y + 1))) continue;
      const glm::vec2 centre(float(x) + 0.5f, float(y) + 0.5f);
      if (const float d = glm::length(centre - pixel); d < best_distance) best_distance = d, best = centre;
    }
  return best;
}

bool MeshSamples::near_background(int index, const glm::vec2& pixel) const {
  const std::vector<float>& depth = depths[size_t(index)];
  const int px = int(pixel.x), py = int(pixel.y);
  for (int y = py - 2; y <= py + 2; ++y)
    for (int x = px - 2; x <= px + 2; ++x)
      if (x < 0 || y < 0 || x >= size || y >= size || depth[size_t(y) * size + x] >= 1.0f) return true;
  return false;
}

std::optional<glm::vec3> MeshSamples::surface_point(int from, const glm::vec2& pixel) const {
  const int x = int(pixel.x), y = int(pixel.y);
  if (x < 0 || y < 0 || x >= size || y >= size) return std::nullopt;
  const float d = depths[size_t(from)][size_t(y) * size + x];
  if (d >= 1.0f) return std::nullopt;
  const glm::vec4 ndc((pixel.x / float(size)) * 2.0f - 1.0f, 1.0f - (pixel.y / float(size)) * 2.0f, d * 2.0f - 1.0f, 1.0f);
  const glm::vec4 world = glm::inverse(view_projection(cameras[size_t(from)])) * ndc;
  return glm::vec3(world) / world.w;
}

MeshSamples render_mesh_samples(const SceneObject& object, const std::vector<glm::vec3>& directions, int size,
                                float distance_diagonals, const std::string& style) {
  MeshSamples s;
  s.size = size;
  s.distance_diagonals = distance_diagonals;
  s.bounds = object.topology.bounds;
  s.directions = directions;
  const FramebufferBinding restore;
  auto renderer = make_renderer(style);
  renderer->prepare(object);
  SampleCanvases canvases(size);
  for (const glm::vec3& d : directions) {
    s.cameras.push_back(sample_camera(s.bounds, d, distance_diagonals));
    std::vector<float> depth;
    s.images.push_back(draw_view(*renderer, canvases, s.cameras.back(), &depth));
    s.depths.push_back(std::move(depth));
  }
  return s;
}

Image render_mesh_view(const SceneObject& object, const glm::vec3& direction, int size, float distance_diagonals,
                       const std::string& style) {
  const FramebufferBinding restore;
  auto renderer = make_renderer(style);
  renderer->prepare(object);
  SampleCanvases canvases(size);
  return draw_view(*renderer, canvases, sample_camera(object.topology.bounds, direction, distance_diagonals), nullptr);
}

TweenCell exact_cell(const MeshSamples& samples, const SceneObject& object, const std::vector<uint16_t>& cell, int count) {
  TweenCell out;
  out.samples = cell;
  const bool pair = cell.size() == 2;
  Camera halfway;
  if (pair)
    halfway = sample_camera(samples.bounds, halfway_direction(samples.directions[cell[0]], samples.directions[cell[1]]),
                            samples.distance_diagonals);
  const glm::mat4 halfway_vp = view_projection(halfway);
  // A hidden vertex none of whose faces meets a sample's camera more squarely than a grazing
  // angle has turned out of sight there (the far flank past its edge-on view) rather than gone
  // behind another part.
  const std::vector<std::vector<float>> facing = facing_cosines(samples, object, cell);
  const float grazing = kGrazingSpans * std::sin(cell_span(samples, cell));
  std::vector<ControlPoint> candidates;
  std::vector<glm::vec2> layout;  // where each candidate sits in the warp's triangulation
  std::vector<bool> on_outline;
  for (size_t vi = 0; vi < object.mesh.positions.size(); ++vi) {
    const glm::vec3& v = object.mesh.positions[vi];
    ControlPoint p;
    // Visible in every sample of the cell; or on the outline of one sample and hidden in the
    // others, where it goes to its projection behind what hides it: that moves the outline of
    // a part that turns into or out of sight (a leg, the far flank) to where it truly goes,
    // and the other samples' mattes are "inside" there too, so the outlines still agree.
    int seen = 0;
    bool seen_on_outline = false, inside_image = true;
    std::vector<bool> seen_in(cell.size(), false);
    for (size_t k = 0; k < cell.size(); ++k) {
      const glm::vec3 projected = samples.project(cell[k], v);
      inside_image = inside_image && projected.x >= 0.0f && projected.y >= 0.0f && projected.x < float(samples.size) &&
                     projected.y < float(samples.size);
      auto at = samples.visible_position(cell[k], v);
      // On the outline a grazing surface's depth changes by more than the slack from one pixel
      // to the next, so the cautious test misses the far edge of a flank about to turn out of
      // sight: there the exact test decides.
      if (!at)
        if (const auto seen_exactly = samples.seen_position(cell[k], v); seen_exactly && samples.near_background(cell[k], *seen_exactly))
          at = seen_exactly;
      p[pair ? 2 * k : k] = at ? *at : glm::vec2(projected);
      seen_in[k] = at.has_value();
      if (at) {
        ++seen;
        seen_on_outline = seen_on_outline || samples.near_background(cell[k], *at);
      }
    }
    if (!inside_image || !(seen == int(cell.size()) || (seen > 0 && seen_on_outline))) continue;
    if (pair) {
      const glm::vec4 clip = halfway_vp * glm::vec4(v, 1.0f);
      p[1] = {(clip.x / clip.w * 0.5f + 0.5f) * float(samples.size), (0.5f - clip.y / clip.w * 0.5f) * float(samples.size)};
    }
    // A point of a surface that has turned out of sight in sample k went there through k's
    // outline, so it lies on that outline in k: its projection behind the front would stretch
    // k's inside out over the background where the other sample still sees the flank.
    for (size_t k = 0; k < cell.size(); ++k) {
      glm::vec2& at = p[pair ? 2 * k : k];
      if (facing[k][vi] > grazing || seen_in[k]) continue;
      if (const auto edge = samples.nearest_outline(cell[k], pair ? p[1] : at, int(kOutlineReach * float(samples.size)))) at = *edge;
    }
    bool outline = false;
    for (size_t k = 0; k < cell.size() && !outline; ++k) outline = samples.near_background(cell[k], p[pair ? 2 * k : k]);
    candidates.push_back(p);
    // Spread where the point is seen: a point that one sample hides lies behind the occluder at
    // the halfway view, among the occluder's points, where spreading would pass it over.
    glm::vec2 at = pair ? p[1] : (p[0] + p[1] + p[2]) / 3.0f;
    if (seen < int(cell.size()))
      for (size_t k = 0; k < cell.size(); ++k)
        if (seen_in[k]) at = p[pair ? 2 * k : k];
    layout.push_back(at);
    on_outline.push_back(outline);
  }
  for (const size_t i : spread_points(layout, on_outline, size_t(count) * 3 / 5, size_t(count))) out.points.push_back(candidates[i]);
  return out;
}

TweenData exact_tween_data(const MeshSamples& samples, const SceneObject& object,
                           const std::vector<std::vector<uint16_t>>& cells, int count) {
  TweenData data;
  data.width = data.height = samples.size;
  data.directions = samples.directions;
  for (const auto& cell : cells) data.cells.push_back(exact_cell(samples, object, cell, count));
  return data;
}

}  // namespace inkwire
