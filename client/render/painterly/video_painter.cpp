#include "client/render/painterly/video_painter.hpp"

#include <algorithm>

#include "client/gl/gl.hpp"
#include "client/render/painterly/painterly_renderer.hpp"

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

std::unique_ptr<VideoPainter> make_video_painter(const std::vector<std::string>& settings, int width, int height) {
  StyleParams params(PainterlyRenderer::params());
  for (const std::string& s : settings) params.set_assignment(s);
  PaintStyle style = paint_style_from_params(params);
  if (params.get_int("brushes") == 0) style.brushes = std::clamp(int(double(style.brushes) * width * height / 60000.0), 500, 30000);
  return std::make_unique<VideoPainter>(style, uint64_t(params.get_int("seed")));
}

}  // namespace inkwire
