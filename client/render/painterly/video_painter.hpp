#pragma once
// Video oil painting (SPEC P9): the same brushes over a live or recorded video. The whole frame
// is the "object"; each frame is painted over the previous painting, so strokes persist and
// only move and recolour (inter-frame coherence) instead of the picture being redone.
#include <memory>
#include <string>
#include <vector>

#include "client/render/painterly/brush_painter.hpp"

namespace inkwire {

class VideoPainter {
 public:
  VideoPainter(const PaintStyle& style, uint64_t seed);
  // Paints `frame` (top row first) over the bound framebuffer's viewport, which keeps the
  // previous painting: the first frame is laid on a full base coat, later ones over it.
  void paint(const Image& frame);
  const BrushPainter& painter() const { return painter_; }

 private:
  BrushPainter painter_;
  Image opaque_;
  bool first_ = true;
};

// A video painter from "painterly" style settings (KEY=VALUE, as for meshes: style file, seed,
// brushes, ...) for frames of width x height. With no brush count set, the count scales with
// the frame so strokes keep their size (the styles' counts suit an object of ~60 000 pixels).
// Throws inkwire::Error for a setting the style does not take.
std::unique_ptr<VideoPainter> make_video_painter(const std::vector<std::string>& settings, int width, int height);

}  // namespace inkwire
