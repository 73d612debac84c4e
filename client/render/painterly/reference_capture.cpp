#include "client/render/painterly/reference_capture.hpp"

#include <algorithm>
#include <cmath>

#include "client/gl/gl.hpp"
#include "client/render/styles.hpp"
#include "common/error.hpp"

namespace inkwire {

using namespace gl;

PixelRect projected_rect(const std::vector<glm::vec3>& points, const glm::mat4& mvp, glm::ivec2 viewport, int margin) {
  if (points.empty()) return {};
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& p : points) {
    const glm::vec4 clip = mvp * glm::vec4(p, 1.0f);
    if (clip.w <= 1e-6f) return {0, 0, viewport.x, viewport.y};
    const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(viewport);
    lo = glm::min(lo, pixel);
    hi = glm::max(hi, pixel);
  }
  const int x0 = std::clamp(int(std::floor(lo.x)) - margin, 0, viewport.x), y0 = std::clamp(int(std::floor(lo.y)) - margin, 0, viewport.y);
  const int x1 = std::clamp(int(std::ceil(hi.x)) + margin, 0, viewport.x), y1 = std::clamp(int(std::ceil(hi.y)) + margin, 0, viewport.y);
  return {x0, y0, x1 - x0, y1 - y0};
}

void ReferenceCapture::use_renderer(const std::string& name) {
  if (name == name_ && reference_) return;
  if (name.find("painterly") != std::string::npos || name.find("oil-filter") != std::string::npos)
    throw Error("reference renderer '" + name + "' is itself a painting: pick default, comic, comic-extended, ...");
  reference_ = make_renderer(name);
  name_ = name;
  if (object_) reference_->prepare(*object_);
}

void ReferenceCapture::prepare(const SceneObject& object) {
  object_ = &object;
  if (reference_) reference_->prepare(object);
}

const Image& ReferenceCapture::capture(const FrameState& frame) {
  if (!object_ || !reference_) throw Error("ReferenceCapture::capture(): no renderer or object yet");
  const FramebufferBinding restore;
  if (!canvas_ || canvas_->size() != frame.viewport) canvas_ = std::make_unique<Canvas>(frame.viewport.x, frame.viewport.y, 1);
  // Outlines and strokes reach a little beyond the bounding box: a few pixels of margin.
  rect_ = projected_rect(object_->mesh.positions, frame.model_view_projection(), frame.viewport, 6);
  if (rect_.empty()) {
    image_ = Image();
    return image_;
  }
  canvas_->bind();
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect_.x, rect_.y, rect_.width, rect_.height);
  glClearColor(0, 0, 0, 0);
  glClearDepthf(1.0f);
  glClearStencil(0);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  FrameState cleared = frame;
  cleared.backdrop = nullptr;  // the capture is cleared to transparent, not to the frame's backdrop
  reference_->draw(cleared);
  glDisable(GL_SCISSOR_TEST);
  image_ = canvas_->read(rect_.x, rect_.y, rect_.width, rect_.height);
  return image_;
}

}  // namespace inkwire
