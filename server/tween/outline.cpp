#include "server/tween/outline.hpp"

#include <glm/geometric.hpp>

#include "common/error.hpp"

namespace inkwire {
namespace {

struct RowEnds {
  int left = -1, right = -1;
};

std::vector<RowEnds> row_ends(const Image& image) {
  std::vector<RowEnds> rows(size_t(image.height));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y)[3] >= 128) {
        if (rows[size_t(y)].left < 0) rows[size_t(y)].left = x;
        rows[size_t(y)].right = x;
      }
  return rows;
}

// The first and last rows that show the object.
std::pair<int, int> extent(const std::vector<RowEnds>& rows) {
  int top = -1, bottom = -1;
  for (int y = 0; y < int(rows.size()); ++y)
    if (rows[size_t(y)].left >= 0) {
      if (top < 0) top = y;
      bottom = y;
    }
  return {top, bottom};
}

}  // namespace

std::vector<Landmark> outline_landmarks(const Image& a, const Image& b, int spacing) {
  if (a.width != b.width || a.height != b.height) throw Error("outline points: the images differ in size");
  if (spacing < 1) throw Error("outline points: spacing must be at least 1");
  const std::vector<RowEnds> ra = row_ends(a), rb = row_ends(b);
  const auto [top_a, bottom_a] = extent(ra);
  const auto [top_b, bottom_b] = extent(rb);
  std::vector<Landmark> out;
  if (top_a < 0 || top_b < 0) return out;
  const int first = std::max(top_a, top_b) + spacing, last = std::min(bottom_a, bottom_b) - spacing;
  for (int y = first; y <= last; y += spacing) {
    const RowEnds& ea = ra[size_t(y)];
    const RowEnds& eb = rb[size_t(y)];
    if (ea.left < 0 || eb.left < 0) continue;
    const float cy = float(y) + 0.5f;
    out.push_back({.source = {float(ea.left) + 0.5f, cy}, .target = {float(eb.left) + 0.5f, cy}, .match = 1.0f});
    out.push_back({.source = {float(ea.right) + 0.5f, cy}, .target = {float(eb.right) + 0.5f, cy}, .match = 1.0f});
  }
  return out;
}

}  // namespace inkwire
