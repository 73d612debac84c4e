#include "client/gl/canvas.hpp"

#include <algorithm>

#include "common/error.hpp"

namespace inkwire {

using namespace gl;

Canvas::Canvas(int width, int height, int samples) : width_(width), height_(height), samples_(samples) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw Error("canvas size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1..16384");
  if (samples < 1 || samples > 16) throw Error("canvas samples must be 1..16");
  const int ms = samples > 1 ? samples : 0;
  colour_ = Renderbuffer::create(GL_RGBA8, width, height, ms);
  depth_stencil_ = Renderbuffer::create(GL_DEPTH24_STENCIL8, width, height, ms);
  draw_fbo_ = Framebuffer::create();
  draw_fbo_.bind();
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_stencil_.id());
  draw_fbo_.check_complete("Canvas");
  if (samples > 1) {
    resolve_colour_ = Renderbuffer::create(GL_RGBA8, width, height, 0);
    resolve_fbo_ = Framebuffer::create();
    resolve_fbo_.bind();
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_colour_.id());
    resolve_fbo_.check_complete("Canvas resolve");
  }
  bind();
}

void Canvas::bind() const {
  draw_fbo_.bind();
  glViewport(0, 0, width_, height_);
}

const Framebuffer& Canvas::resolved() const {
  if (samples_ <= 1) return draw_fbo_;
  draw_fbo_.bind(GL_READ_FRAMEBUFFER);
  resolve_fbo_.bind(GL_DRAW_FRAMEBUFFER);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  return resolve_fbo_;
}

Image Canvas::read() const { return read(0, 0, width_, height_); }

Image Canvas::read(int x, int y, int width, int height) const {
  if (x < 0 || y < 0 || width <= 0 || height <= 0 || x + width > width_ || y + height > height_)
    throw Error("Canvas::read(): rectangle outside the canvas");
  resolved().bind(GL_READ_FRAMEBUFFER);
  Image image(width, height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  check_error("Canvas::read");
  flip_rows(image);  // GL rows run bottom-up
  bind();
  return image;
}

std::vector<float> Canvas::read_depth() const {
  if (samples_ > 1) throw Error("Canvas::read_depth(): multisampled depth cannot be read back");
  draw_fbo_.bind(GL_READ_FRAMEBUFFER);
  std::vector<float> depth(size_t(width_) * height_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  check_error("Canvas::read_depth");
  std::vector<float> upright(depth.size());
  for (int y = 0; y < height_; ++y)
    std::copy_n(&depth[size_t(height_ - 1 - y) * width_], width_, &upright[size_t(y) * width_]);
  bind();
  return upright;
}

void Canvas::present_to_default(glm::ivec2 target) const {
  resolved().bind(GL_READ_FRAMEBUFFER);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, target.x, target.y, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  bind();
}

FramebufferBinding::FramebufferBinding() {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer_);
  glGetIntegerv(GL_VIEWPORT, &viewport_.x);
}

FramebufferBinding::~FramebufferBinding() {
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(framebuffer_));
  glViewport(viewport_.x, viewport_.y, viewport_.z, viewport_.w);
}

}  // namespace inkwire
