#pragma once
// The object's visual hull (SPEC T25): what every matte allows, carved from a grid of voxels
// (shape from silhouette: a voxel stays when it falls inside the object in every photo), seen
// again from each photo as its silhouette (how well the hull explains that photo's matte: IoU)
// and as a depth map (which depth_refinement.hpp then takes in where the hull bulges).
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

#include "server/products/turntable_camera.hpp"

namespace inkwire {

// A photo's silhouette: 1 where the object is, row after row.
struct Silhouette {
  int width = 0, height = 0;
  std::vector<uint8_t> inside;
  bool at(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height && inside[size_t(y * width + x)]; }
};

struct VisualHull {
  glm::vec3 low{0.0f};  // the grid's corner (object frame)
  float voxel = 0;      // its cells' side
  glm::ivec3 cells{0};  // a side
  std::vector<uint8_t> kept;  // x fastest, then y, then z
  bool at(int x, int y, int z) const {
    return x >= 0 && y >= 0 && z >= 0 && x < cells.x && y < cells.y && z < cells.z && kept[size_t((z * cells.y + y) * cells.x + x)];
  }
  glm::vec3 centre(int x, int y, int z) const { return low + voxel * (glm::vec3(float(x), float(y), float(z)) + 0.5f); }
  size_t count() const;
};

// Carves a grid of `n` cells along its longest side (cubes), over a box that holds whatever the
// silhouettes of `views` (pictures of the camera's size) allow, keeping the cells inside every
// silhouette. A matte that fails (a white roof taken for a white backdrop) takes its part of the
// object away for every photo: photo_shape.hpp says which photos the hull then does not explain.
VisualHull carve_hull(const TurntableCamera& camera, const std::vector<PhotoView>& views, const std::vector<Silhouette>& silhouettes, int n);

// The hull as seen by `view`: its silhouette (every kept cell drawn as the square its size covers
// at its depth) and, where `depth` is given, the depth (distance ahead of the camera) of the
// nearest cell at each pixel, 0 where none.
Silhouette hull_silhouette(const VisualHull& hull, const TurntableCamera& camera, const PhotoView& view, std::vector<float>* depth = nullptr);

// Intersection over union of two silhouettes of one size.
double silhouette_iou(const Silhouette& a, const Silhouette& b);

// The hull's outer faces as a triangle mesh in PLY (ASCII), in the object frame.
void write_hull_ply(const VisualHull& hull, const std::filesystem::path& file);

}  // namespace inkwire
