#include "client/render/painterly/video_painter.hpp"

#include "client/gl/gl.hpp"

namespace inkwire {

VideoPainter::VideoPainter(const PaintStyle& style, uint64_t seed) {
  PaintStyle full_base = style;
  full_base.underpaint = 1.0f;  // the first frame's base coat hides whatever was there before
  painter_.set_style(full_base, seed);
}

void VideoPainter::paint(const Image& frame) {
  GLint viewport[4];
  gl::glGetIntegerv(GL_VIEWPORT, viewport);
  opaque_ = frame;
  for (size_t i = 3; i < opaque_.pixels.size(); i += 4) opaque_.pixels[i] = 255;  // every pixel is paintable
  const PixelRect rect{viewport[0], viewport[1], viewport[2], viewport[3]};
  painter_.paint(opaque_, rect, /*underpaint=*/first_, /*settle=*/0);
  first_ = false;
}

}  // namespace inkwire
