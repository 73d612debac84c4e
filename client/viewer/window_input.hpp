#pragma once
// What a person does to the client window, gathered from GLFW's callbacks between frames: the
// orbit they drag and zoom, the keys they press (Tab / Shift-Tab: style, arrows: view; on a
// product P: present, F: follow the presenter) and whether anything happened at all, so an idle
// window need not redraw. Input the panel takes (ImGui wants the mouse or keyboard) is left to
// the panel.
#include "protocol/messages.hpp"

struct GLFWwindow;

namespace inkwire {

// The user's orbit, kept as angles so dragging never rolls the camera.
struct Orbit {
  float azimuth = 30, elevation = 20, distance = 1.4f;
  bool dragging = false;
  bool changed = false;  // moved by the user since the last frame
  double last_x = 0, last_y = 0;
  bool pointer_seen = false;  // a motion event has given last_x, last_y

  void from(const protocol::CameraPose& pose);
};

// A let-go drag keeps turning and slows down, as a physical turntable does. The browser's element
// keeps the same rule (client/web/common/inertia.js, pinned by warp-vectors.json "inertia").
inline constexpr float kMaxTurnSpeed = 360.0f;   // degrees a second a fling may keep: a turn a second
inline constexpr float kInertiaSeconds = 0.4f;   // the speed falls by a factor e in this long
inline constexpr float kInertiaStop = 2.0f;      // degrees a second below which it stops
inline constexpr float kDragDegreesPerPixel = 0.4f;  // a drag turns the view this far a pixel, either way

// The speed a drag leaves: the last moments of the drag smoothed, a drag of `degrees` in
// `seconds` the newest, at most kMaxTurnSpeed either way.
float dragged_velocity(float velocity, float degrees, double seconds);
// `seconds` of coasting at `velocity`: how far it turns, and the speed left (0 once too slow).
struct Coasted {
  float turn, velocity;
};
Coasted coast(float velocity, double seconds);

struct Inertia {
  float velocity = 0.0f;  // degrees per second
  float last_azimuth = 0.0f;
  bool was_dragging = false;

  void follow(Orbit& orbit, double dt);
  bool moving() const { return velocity != 0.0f; }
  void stop() { velocity = 0.0f; }
};

struct WindowInput {
  Orbit orbit;
  int style_step = 0;        // Tab +1, Shift-Tab -1, since the last frame
  int view_step_x = 0;       // Right +1, Left -1
  int view_step_y = 0;       // Up +1, Down -1
  bool toggle_present = false;  // P
  bool toggle_follow = false;   // F
  bool toggle_mute = false;     // M, in a call
  bool toggle_camera = false;   // C, in a call
  long events = 0;           // every input or window event so far: a change means redraw

  // Installs the callbacks; call before ImGui's GLFW backend, which chains to them.
  void attach(GLFWwindow* window);
  // Key presses taken since the last call, then forgotten.
  void clear_steps() {
    style_step = view_step_x = view_step_y = 0;
    toggle_present = toggle_follow = toggle_mute = toggle_camera = false;
  }
};

}  // namespace inkwire
