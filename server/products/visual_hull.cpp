#include "server/products/visual_hull.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <numeric>
#include <thread>

#include <glm/common.hpp>
#include <glm/trigonometric.hpp>

#include "common/error.hpp"

namespace inkwire {
namespace {

// How far from the axis (horizontally) and from the origin (vertically) the object can reach:
// the silhouettes' furthest pixels from the axis's column and the middle row, back at the
// distance of the axis, grown for the nearer side's perspective and a margin.
glm::vec2 reach(const TurntableCamera& camera, const std::vector<Silhouette>& silhouettes) {
  float across = 1, up = 1;
  for (const Silhouette& s : silhouettes)
    for (int y = 0; y < s.height; ++y)
      for (int x = 0; x < s.width; ++x)
        if (s.inside[size_t(y * s.width + x)]) {
          across = std::max(across, std::abs(float(x) + 0.5f - camera.axis_x));
          up = std::max(up, std::abs(float(y) + 0.5f - 0.5f * float(camera.height)));
        }
  const float radius = std::min(0.8f, 1.25f * across / (camera.focal_px + across));
  float steepest = 0;
  for (const float e : camera.elevations_deg) steepest = std::max(steepest, std::abs(glm::radians(e)));
  const float height = std::min(1.5f, 1.25f * (up / camera.focal_px * (1 + radius) + radius) / std::max(std::cos(steepest), 0.3f));
  return {radius, height};
}

// The convex outline of `points`, counter-clockwise (Andrew's monotone chain).
std::vector<glm::vec2> convex_outline(std::array<glm::vec2, 8> points) {
  std::sort(points.begin(), points.end(), [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const auto turn = [](const glm::vec2& o, const glm::vec2& a, const glm::vec2& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<glm::vec2> hull(16);
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

bool inside_outline(const std::vector<glm::vec2>& outline, const glm::vec2& p) {
  for (size_t i = 0; i < outline.size(); ++i) {
    const glm::vec2 &a = outline[i], &b = outline[(i + 1) % outline.size()];
    if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < 0) return false;
  }
  return true;
}

}  // namespace

size_t VisualHull::count() const { return size_t(std::count(kept.begin(), kept.end(), uint8_t(1))); }

namespace {

// Every cell of `hull`'s grid that falls outside a silhouette carved away; the grid's slices
// shared among the machine's cores.
void carve(VisualHull& hull, const TurntableCamera& camera, const std::vector<PhotoView>& views, const std::vector<Silhouette>& silhouettes) {
  // Each view's frame worked out once: a point's camera coordinates are origin + x dx + y dy + z dz.
  struct Frame {
    glm::vec3 origin, dx, dy, dz;
  };
  std::vector<Frame> frames;
  for (const PhotoView& view : views) {
    const glm::vec3 origin = to_camera(camera, view, glm::vec3(0.0f));
    frames.push_back({origin, to_camera(camera, view, glm::vec3(1, 0, 0)) - origin, to_camera(camera, view, glm::vec3(0, 1, 0)) - origin,
                      to_camera(camera, view, glm::vec3(0, 0, 1)) - origin});
  }
  const auto slices = [&](int from, int step) {
    for (int z = from; z < hull.cells.z; z += step)
      for (int y = 0; y < hull.cells.y; ++y)
        for (int x = 0; x < hull.cells.x; ++x) {
          const glm::vec3 p = hull.centre(x, y, z);
          bool inside = true;
          for (size_t v = 0; v < frames.size() && inside; ++v) {
            const Frame& f = frames[v];
            const glm::vec3 c = f.origin + p.x * f.dx + p.y * f.dy + p.z * f.dz;
            if (c.z <= 1e-3f) {
              inside = false;  // behind a camera: that camera would be inside the object
              break;
            }
            const glm::vec2 pixel = to_pixel(camera, c);
            inside = silhouettes[v].at(int(std::floor(pixel.x)), int(std::floor(pixel.y)));
          }
          hull.kept[size_t((z * hull.cells.y + y) * hull.cells.x + x)] = inside;
        }
  };
  const int workers = int(std::clamp<unsigned>(std::thread::hardware_concurrency(), 1, 8));
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w) threads.emplace_back(slices, w, workers);
  for (std::thread& t : threads) t.join();
}

VisualHull grid_over(const glm::vec3& low, const glm::vec3& high, int n) {
  VisualHull hull;
  const glm::vec3 size = high - low;
  hull.voxel = std::max({size.x, size.y, size.z}) / float(n);
  hull.cells = glm::max(glm::ivec3(glm::ceil(size / hull.voxel)), glm::ivec3(1));
  hull.low = 0.5f * (low + high) - 0.5f * hull.voxel * glm::vec3(hull.cells);
  hull.kept.assign(size_t(hull.cells.x) * size_t(hull.cells.y) * size_t(hull.cells.z), 1);
  return hull;
}

}  // namespace

VisualHull carve_hull(const TurntableCamera& camera, const std::vector<PhotoView>& views, const std::vector<Silhouette>& silhouettes, int n) {
  if (views.size() != silhouettes.size() || views.empty()) throw Error("a hull needs one silhouette per photo");
  // First over a box that surely holds the object, coarsely; then over what that kept, grown by
  // one of its cells, at `n` cells along the longest side.
  const glm::vec2 r = reach(camera, silhouettes);
  VisualHull coarse = grid_over(glm::vec3(-r.x, -r.y, -r.x), glm::vec3(r.x, r.y, r.x), std::max(16, n / 2));
  carve(coarse, camera, views, silhouettes);
  glm::ivec3 lo(coarse.cells), hi(-1);
  for (int z = 0; z < coarse.cells.z; ++z)
    for (int y = 0; y < coarse.cells.y; ++y)
      for (int x = 0; x < coarse.cells.x; ++x)
        if (coarse.at(x, y, z)) lo = glm::min(lo, glm::ivec3(x, y, z)), hi = glm::max(hi, glm::ivec3(x, y, z));
  if (hi.x < 0) return coarse;  // nothing agrees
  VisualHull hull = grid_over(coarse.low + coarse.voxel * glm::vec3(lo - 1), coarse.low + coarse.voxel * glm::vec3(hi + 2), n);
  carve(hull, camera, views, silhouettes);
  return hull;
}

Silhouette hull_silhouette(const VisualHull& hull, const TurntableCamera& camera, const PhotoView& view, std::vector<float>* depth) {
  Silhouette out{.width = camera.width, .height = camera.height, .inside = std::vector<uint8_t>(size_t(camera.width) * size_t(camera.height), 0)};
  if (depth) depth->assign(out.inside.size(), 0.0f);
  // The object frame's axes in the camera's frame: a cell's corners are its centre plus or minus these.
  const glm::vec3 origin = to_camera(camera, view, glm::vec3(0.0f));
  const glm::vec3 right = to_camera(camera, view, glm::vec3(1, 0, 0)) - origin, up = to_camera(camera, view, glm::vec3(0, 1, 0)) - origin,
                  ahead = to_camera(camera, view, glm::vec3(0, 0, 1)) - origin;
  for (int z = 0; z < hull.cells.z; ++z)
    for (int y = 0; y < hull.cells.y; ++y)
      for (int x = 0; x < hull.cells.x; ++x) {
        if (!hull.at(x, y, z)) continue;
        // A cell with kept neighbours on all six sides is hidden behind them.
        if (hull.at(x - 1, y, z) && hull.at(x + 1, y, z) && hull.at(x, y - 1, z) && hull.at(x, y + 1, z) && hull.at(x, y, z - 1) && hull.at(x, y, z + 1))
          continue;
        const glm::vec3 c = to_camera(camera, view, hull.centre(x, y, z));
        if (c.z <= 1e-3f) continue;
        // The cube's outline in the picture: the convex hull of its eight corners; the pixels
        // whose centres it covers are the object's.
        std::array<glm::vec2, 8> corners;
        bool behind = false;  // a cell reaching behind the camera is left out (a camera inside the object)
        for (int k = 0; k < 8; ++k) {
          const glm::vec3 corner = c + 0.5f * hull.voxel * (float(k & 1 ? 1 : -1) * right + float(k & 2 ? 1 : -1) * up + float(k & 4 ? 1 : -1) * ahead);
          behind = behind || corner.z <= 1e-3f;
          corners[size_t(k)] = to_pixel(camera, corner);
        }
        if (behind) continue;
        const std::vector<glm::vec2> outline = convex_outline(corners);
        glm::vec2 lo(1e9f), hi(-1e9f);
        for (const glm::vec2& q : outline) lo = glm::min(lo, q), hi = glm::max(hi, q);
        const int x0 = std::max(0, int(std::ceil(lo.x - 0.5f))), x1 = std::min(camera.width - 1, int(std::floor(hi.x - 0.5f)));
        const int y0 = std::max(0, int(std::ceil(lo.y - 0.5f))), y1 = std::min(camera.height - 1, int(std::floor(hi.y - 0.5f)));
        for (int py = y0; py <= y1; ++py)
          for (int px = x0; px <= x1; ++px) {
            if (!inside_outline(outline, glm::vec2(float(px) + 0.5f, float(py) + 0.5f))) continue;
            const size_t i = size_t(py * camera.width + px);
            out.inside[i] = 1;
            if (depth && ((*depth)[i] == 0 || c.z < (*depth)[i])) (*depth)[i] = c.z;
          }
      }
  return out;
}

double silhouette_iou(const Silhouette& a, const Silhouette& b) {
  if (a.width != b.width || a.height != b.height) throw Error("silhouettes of different sizes");
  size_t both = 0, either = 0;
  for (size_t i = 0; i < a.inside.size(); ++i) {
    both += a.inside[i] && b.inside[i];
    either += a.inside[i] || b.inside[i];
  }
  return either ? double(both) / double(either) : 1.0;
}

void write_hull_ply(const VisualHull& hull, const std::filesystem::path& file) {
  // Every face between a kept cell and an empty one, as two triangles facing out.
  std::vector<glm::vec3> vertices;
  const glm::ivec3 sides[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int z = 0; z < hull.cells.z; ++z)
    for (int y = 0; y < hull.cells.y; ++y)
      for (int x = 0; x < hull.cells.x; ++x) {
        if (!hull.at(x, y, z)) continue;
        for (const glm::ivec3& n : sides) {
          if (hull.at(x + n.x, y + n.y, z + n.z)) continue;
          // The face's two other axes, in an order that makes its corners turn counter-clockwise seen from outside.
          const int axis = n.x ? 0 : n.y ? 1 : 2, sign = n.x + n.y + n.z;
          glm::vec3 u(0.0f), w(0.0f);
          u[(axis + 1) % 3] = 1, w[(axis + 2) % 3] = 1;
          if (sign < 0) std::swap(u, w);
          const glm::vec3 centre = hull.centre(x, y, z) + 0.5f * hull.voxel * glm::vec3(n);
          const glm::vec3 a = centre + 0.5f * hull.voxel * (-u - w), b = centre + 0.5f * hull.voxel * (u - w), c = centre + 0.5f * hull.voxel * (u + w),
                          d = centre + 0.5f * hull.voxel * (-u + w);
          for (const glm::vec3& corner : {a, b, c, d}) vertices.push_back(corner);
        }
      }
  std::ofstream out(file);
  if (!out) throw Error("cannot write " + file.string());
  const size_t quads = vertices.size() / 4;
  out << "ply\nformat ascii 1.0\ncomment inkwire visual hull, object frame, units of the camera's distance to the axis\nelement vertex "
      << vertices.size() << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << quads * 2
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const glm::vec3& v : vertices) out << v.x << ' ' << v.y << ' ' << v.z << '\n';
  for (size_t q = 0; q < quads; ++q) out << "3 " << 4 * q << ' ' << 4 * q + 1 << ' ' << 4 * q + 2 << "\n3 " << 4 * q << ' ' << 4 * q + 2 << ' ' << 4 * q + 3 << '\n';
  if (!out) throw Error("cannot write " + file.string());
}

}  // namespace inkwire
