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

// WebGL2 reads no depth back (readPixels takes colour only), so both targets read it the way
// WebGL2 can: the depth copied into a depth texture, drawn into colour as its 24 bits (red the
// highest), and read as colour.
struct Canvas::DepthCopy {
  DepthCopy(int width, int height)
      : depth(Texture::depth_stencil(width, height)),
        depth_fbo(Framebuffer::create()),
        packed(Renderbuffer::create(GL_RGBA8, width, height, 0)),
        packed_fbo(Framebuffer::create()),
        program(Program::from_files({"common/packed_depth.vert", "common/packed_depth.frag"})),
        empty(VertexArray::create()) {
    depth_fbo.bind();
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth.id(), 0);
    depth_fbo.check_complete("Canvas depth copy");
    packed_fbo.bind();
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, packed.id());
    packed_fbo.check_complete("Canvas packed depth");
  }
  Texture depth;
  Framebuffer depth_fbo;
  Renderbuffer packed;
  Framebuffer packed_fbo;
  Program program;
  VertexArray empty;
};

Canvas::Canvas(Canvas&&) noexcept = default;
Canvas& Canvas::operator=(Canvas&&) noexcept = default;
Canvas::~Canvas() = default;

std::vector<float> Canvas::read_depth() const {
  if (samples_ > 1) throw Error("Canvas::read_depth(): multisampled depth cannot be read back");
  if (!depth_copy_) depth_copy_ = std::make_unique<DepthCopy>(width_, height_);
  const DepthCopy& copy = *depth_copy_;
  draw_fbo_.bind(GL_READ_FRAMEBUFFER);
  copy.depth_fbo.bind(GL_DRAW_FRAMEBUFFER);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
  copy.packed_fbo.bind();
  glViewport(0, 0, width_, height_);
  const GLboolean depth_test = glIsEnabled(GL_DEPTH_TEST), blend = glIsEnabled(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  copy.program.use();
  copy.depth.bind(0);
  copy.program.set("depth", 0);
  copy.empty.bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  if (depth_test) glEnable(GL_DEPTH_TEST);
  if (blend) glEnable(GL_BLEND);
  std::vector<uint8_t> bytes(size_t(width_) * size_t(height_) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
  check_error("Canvas::read_depth");
  std::vector<float> upright(size_t(width_) * size_t(height_));
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const uint8_t* p = &bytes[(size_t(height_ - 1 - y) * size_t(width_) + size_t(x)) * 4];  // GL rows run bottom-up
      upright[size_t(y) * size_t(width_) + size_t(x)] = float(double(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]) / 16777215.0);
    }
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
