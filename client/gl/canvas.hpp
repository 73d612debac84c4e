#pragma once
// The render target every renderer draws into: an off-screen framebuffer with colour, depth and
// stencil, optionally multisampled. Read back as an upright RGBA image, or shown in a window.
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "client/gl/resources.hpp"
#include "common/image.hpp"

namespace inkwire {

class Canvas {
 public:
  // `samples` 1 = no multisampling. Throws inkwire::Error if the driver refuses the format.
  Canvas(int width, int height, int samples = 1);
  Canvas(Canvas&&) noexcept;
  Canvas& operator=(Canvas&&) noexcept;
  ~Canvas();

  void bind() const;  // binds for drawing and sets the viewport to the whole canvas
  int width() const { return width_; }
  int height() const { return height_; }
  glm::ivec2 size() const { return {width_, height_}; }
  int samples() const { return samples_; }

  // Resolves multisampling and reads the colour as an upright (top row first) RGBA image.
  Image read() const;
  // The same for the rectangle whose lower-left pixel is (x, y) in GL window coordinates.
  Image read(int x, int y, int width, int height) const;
  // Window depth (0 near .. 1 far) of every pixel, top row first, to the depth buffer's 24 bits.
  // Single-sampled canvases only.
  std::vector<float> read_depth() const;
  // Copies the colour into the default framebuffer (a window), scaled to `target` pixels.
  void present_to_default(glm::ivec2 target) const;

 private:
  const gl::Framebuffer& resolved() const;
  int width_, height_, samples_;
  gl::Framebuffer draw_fbo_, resolve_fbo_;
  gl::Renderbuffer colour_, depth_stencil_, resolve_colour_;
  struct DepthCopy;  // what read_depth() draws the depth through, made when first asked
  mutable std::unique_ptr<DepthCopy> depth_copy_;
};

// Saves the bound draw framebuffer and viewport, and restores them when it goes.
class FramebufferBinding {
 public:
  FramebufferBinding();
  ~FramebufferBinding();
  FramebufferBinding(const FramebufferBinding&) = delete;
  FramebufferBinding& operator=(const FramebufferBinding&) = delete;
  glm::ivec4 viewport() const { return viewport_; }

 private:
  int framebuffer_ = 0;
  glm::ivec4 viewport_{0};
};

}  // namespace inkwire
