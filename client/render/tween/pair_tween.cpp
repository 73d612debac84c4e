#include "client/render/tween/pair_tween.hpp"

#include <algorithm>

#include "common/error.hpp"

namespace inkwire {

namespace {

int checked_width(const Image& a, const Image& b, const TweenCell& cell) {
  if (a.width != b.width || a.height != b.height) throw Error("PairTween: the two images differ in size");
  if (!cell.is_pair()) throw Error("PairTween: the cell is not a pair");
  return a.width;
}

}  // namespace

PairTween::PairTween(const Image& a, const Image& b, const TweenCell& cell)
    : a_(make_sample_texture(a)), b_(make_sample_texture(b)), warper_(checked_width(a, b, cell), a.height),
      mesh_(warper_.add_mesh(build_warp_mesh(cell, a.width, a.height))) {}

Image PairTween::tween(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  const WarpSource both[] = {{&a_, 0, 1.0f - t}, {&b_, 2, t}};
  warper_.render(mesh_, path_weights(t), both);
  return warper_.read();
}

Image PairTween::crossfade(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  // Both images unwarped: the mesh where it lies in `a`, and both read at those same pixels.
  const WarpSource both[] = {{&a_, 0, 1.0f - t}, {&b_, 0, t}};
  warper_.render(mesh_, {1, 0, 0}, both);
  return warper_.read();
}

}  // namespace inkwire
