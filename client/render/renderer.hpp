#pragma once
// The one interface every renderer implements (comic, sketch, hatching, painterly, tween, ...).
// A renderer draws into whatever framebuffer is bound (window or off-screen canvas): it never
// knows which. prepare() runs once per object; draw() runs every frame.
#include <map>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "client/render/scene_object.hpp"
#include "common/camera.hpp"
#include "common/style_params.hpp"

namespace inkwire {

class Backdrop;

struct FrameState {
  Camera camera;
  glm::mat4 model{1.0f};           // object pose
  glm::vec3 light_direction{0, 0, 1};  // world space, unit, pointing toward the light
  glm::ivec2 viewport{620, 500};
  double time_seconds = 0.0;       // animation time (drives boiling lines, brush motion, ...)
  long frame = 0;
  // What the framebuffer was cleared to before this frame's objects, when the caller knows:
  // renderers with see-through surfaces (hatching) then draw it under their ink in one opaque
  // pass. Null: unknown, so they lay depth first and blend over whatever is there.
  const Backdrop* backdrop = nullptr;
  // The object's depth is in the depth buffer already, laid as hidden-line removal lays it (a
  // renderer drawing lines over its own opaque surface says so), so line renderers skip their
  // depth pass.
  bool depth_laid = false;

  glm::mat4 view() const { return camera.view(); }
  glm::mat4 projection() const { return camera.projection(float(viewport.x) / float(viewport.y)); }
  glm::mat4 model_view_projection() const { return projection() * view() * model; }
  // The viewer in the object's own coordinates.
  glm::vec3 eye_in_object_space() const { return glm::vec3(glm::inverse(model) * glm::vec4(camera.position, 1.0f)); }
  // The light rotated into object space once per frame instead of rotating every normal
  // (SPEC C2). Assumes the model matrix is a rotation, translation and uniform scale.
  glm::vec3 light_in_object_space() const {
    return glm::normalize(glm::transpose(glm::mat3(model)) * light_direction);
  }
};

// The frame a session's scene is drawn in: its camera, its object's pose, the camera's default
// light, the animation time and frame, and the backdrop laid under it. The native client and the
// browser's module both draw scenes in this frame.
inline FrameState scene_frame(glm::ivec2 viewport, const Camera& camera, const glm::mat4& model, double time_seconds, long frame,
                              const Backdrop* backdrop) {
  FrameState f;
  f.viewport = viewport;
  f.camera = camera;
  f.model = model;
  f.light_direction = default_light_direction(camera);
  f.time_seconds = time_seconds;
  f.frame = frame;
  f.backdrop = backdrop;
  return f;
}

class Renderer {
 public:
  virtual ~Renderer() = default;
  // Applies style parameters (validated by StyleParams). May be called again between frames.
  virtual void configure(const StyleParams& params) = 0;
  // Uploads / precomputes what this renderer needs for the object. Called once per object.
  virtual void prepare(const SceneObject& object) = 0;
  // Draws the prepared object over whatever the framebuffer holds (backdrop already drawn).
  virtual void draw(const FrameState& frame) = 0;
  // Figures about the last frame (e.g. "front_faces", "edges_drawn"), for benchmarks and tests.
  virtual std::map<std::string, double> counters() const { return {}; }
  // True when the last draw left the object's depth laid as hidden-line removal lays it (an
  // opaque surface drawn that way), so lines drawn next over it need no depth pass of their own.
  virtual bool left_line_depth() const { return false; }
};

}  // namespace inkwire
