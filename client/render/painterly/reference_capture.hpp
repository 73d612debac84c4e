#pragma once
// SPEC P1: the object drawn off-screen by another renderer (default, comic, ...), limited to
// the screen rectangle of its projected bounding box. The capture is cleared to transparent
// first, so its alpha is the object's matte.
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "client/gl/canvas.hpp"
#include "client/render/renderer.hpp"

namespace inkwire {

// A rectangle of window pixels: lower-left corner (x, y) in GL coordinates, width, height.
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
};

// The screen rectangle of `points` under `model_view_projection` (the object's bounding box on
// screen, as tight as its vertices make it; a 3D box's corners would give a rectangle up to
// six times the object's area at oblique views), grown by `margin` pixels and clipped to the
// viewport; the whole viewport when any point is behind the viewer.
PixelRect projected_rect(const std::vector<glm::vec3>& points, const glm::mat4& model_view_projection, glm::ivec2 viewport, int margin);

class ReferenceCapture {
 public:
  // Picks the renderer whose picture is captured (nothing happens when the name is unchanged).
  // Throws inkwire::Error for unknown styles and for painterly ones: a painting of a painting
  // would recurse.
  void use_renderer(const std::string& name);
  void prepare(const SceneObject& object);

  // Draws the object for `frame` into an off-screen canvas the size of the frame's viewport,
  // scissored to the object's rectangle, and reads back that rectangle only. Leaves the
  // caller's framebuffer and viewport bound again. Returns the image (top row first).
  const Image& capture(const FrameState& frame);
  PixelRect rect() const { return rect_; }
  double pixels() const { return double(rect_.width) * rect_.height; }

 private:
  std::string name_;
  std::unique_ptr<Renderer> reference_;
  const SceneObject* object_ = nullptr;
  std::unique_ptr<Canvas> canvas_;
  Image image_;
  PixelRect rect_;
};

}  // namespace inkwire
