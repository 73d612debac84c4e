#pragma once
// Sample sets rendered from a mesh (SPEC T1a): the object drawn by any style from each view
// direction, with its depth, so exact control points come from projected visible vertices and
// the true position of any pixel in another sample is known (for measuring landmarks, T7).
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "client/render/scene_object.hpp"
#include "common/camera.hpp"
#include "common/image.hpp"
#include "common/tween/tween_data.hpp"

namespace inkwire {

struct MeshSamples {
  int size = 0;  // square images, size x size pixels
  float distance_diagonals = 0.0f;
  Bounds bounds;
  std::vector<glm::vec3> directions;
  std::vector<Camera> cameras;
  std::vector<Image> images;               // RGBA, transparent where the object is not
  std::vector<std::vector<float>> depths;  // window depth per pixel, top row first (1 = nothing)

  // Where `point` (object space) lands in sample `index`, in pixels, and its window depth.
  glm::vec3 project(int index, const glm::vec3& point) const;
  // The pixel when `point` is inside the image and nothing nearer lies within a pixel of it: a
  // cautious test, for control points (a vertex beside an occluding edge would drag it along).
  std::optional<glm::vec2> visible_position(int index, const glm::vec3& point) const;
  // The pixel when `point` is inside the image and is what the pixel it falls in shows: the exact
  // test, for checking a correspondence (a point beside an occluding edge is still seen).
  std::optional<glm::vec2> seen_position(int index, const glm::vec3& point) const;
  // True when background (nothing drawn) lies within 2 pixels of `pixel`: an outline point.
  bool near_background(int index, const glm::vec2& pixel) const;
  // The object pixel next to background nearest to `pixel`, within `reach` pixels.
  std::optional<glm::vec2> nearest_outline(int index, const glm::vec2& pixel, int reach) const;
  // The surface point seen at `pixel` of sample `from`, when there is one.
  std::optional<glm::vec3> surface_point(int from, const glm::vec2& pixel) const;

 private:
  // The pixel when no depth within `reach` pixels of where `point` falls is nearer than it.
  std::optional<glm::vec2> position_in_front(int index, const glm::vec3& point, int reach) const;
};

// Needs a current GL context. `style` is any registered style (default: the default renderer).
MeshSamples render_mesh_samples(const SceneObject& object, const std::vector<glm::vec3>& directions, int size,
                                float distance_diagonals, const std::string& style = "default");

// Renders one more view of the same set-up (e.g. the true in-between view to compare against).
Image render_mesh_view(const SceneObject& object, const glm::vec3& direction, int size, float distance_diagonals,
                       const std::string& style = "default");

// Exact control points for a cell of `samples` (2 or 3): mesh vertices visible in every sample of
// the cell, `count` of them spread by farthest-point sampling on their mid-path positions (which
// picks the outline first). A pair's halfway position is the vertex projected from the view
// halfway between its samples.
TweenCell exact_cell(const MeshSamples& samples, const SceneObject& object, const std::vector<uint16_t>& cell, int count);

TweenData exact_tween_data(const MeshSamples& samples, const SceneObject& object,
                           const std::vector<std::vector<uint16_t>>& cells, int count);

}  // namespace inkwire
