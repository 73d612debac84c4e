#include "client/viewer/window_input.hpp"

#include <algorithm>
#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <imgui.h>

#include "common/camera.hpp"

namespace inkwire {

void Orbit::from(const protocol::CameraPose& pose) {
  const SceneOrbit o = scene_orbit_of(pose.position, pose.target);
  azimuth = o.azimuth, elevation = o.elevation, distance = o.distance;
}

float dragged_velocity(float velocity, float degrees, double seconds) {
  return std::clamp(0.7f * velocity + 0.3f * float(degrees / seconds), -kMaxTurnSpeed, kMaxTurnSpeed);
}

Coasted coast(float velocity, double seconds) {
  if (std::abs(velocity) <= kInertiaStop) return {0.0f, 0.0f};
  return {velocity * float(seconds), velocity * float(std::exp(-seconds / kInertiaSeconds))};
}

void Inertia::follow(Orbit& orbit, double dt) {
  if (dt <= 0.0) return;
  if (orbit.dragging) {
    velocity = was_dragging ? dragged_velocity(velocity, orbit.azimuth - last_azimuth, dt) : 0.0f;
  } else {
    const Coasted c = coast(velocity, dt);
    orbit.azimuth += c.turn;
    velocity = c.velocity;
  }
  was_dragging = orbit.dragging;
  last_azimuth = orbit.azimuth;
}

namespace {

WindowInput& input_of(GLFWwindow* w) { return *static_cast<WindowInput*>(glfwGetWindowUserPointer(w)); }

void on_key(GLFWwindow* w, int key, int, int action, int mods) {
  WindowInput& in = input_of(w);
  ++in.events;
  // Keys typed into the panel's fields are the panel's.
  if ((action != GLFW_PRESS && action != GLFW_REPEAT) || ImGui::GetIO().WantTextInput) return;
  switch (key) {
    case GLFW_KEY_TAB: in.style_step += (mods & GLFW_MOD_SHIFT) ? -1 : 1; break;
    case GLFW_KEY_RIGHT: ++in.view_step_x; break;
    case GLFW_KEY_LEFT: --in.view_step_x; break;
    case GLFW_KEY_UP: ++in.view_step_y; break;
    case GLFW_KEY_DOWN: --in.view_step_y; break;
    case GLFW_KEY_P: in.toggle_present = !in.toggle_present; break;
    case GLFW_KEY_F: in.toggle_follow = !in.toggle_follow; break;
    case GLFW_KEY_M: in.toggle_mute = !in.toggle_mute; break;
    case GLFW_KEY_C: in.toggle_camera = !in.toggle_camera; break;
    default: break;
  }
}

}  // namespace

void WindowInput::attach(GLFWwindow* window) {
  glfwSetWindowUserPointer(window, this);
  glfwSetKeyCallback(window, on_key);
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned) { ++input_of(w).events; });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    WindowInput& in = input_of(w);
    ++in.events;
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    if (action == GLFW_PRESS && ImGui::GetIO().WantCaptureMouse) return;  // a click on the panel
    // The drag starts where the pointer was when pressed: the last position the motion events
    // gave, not glfwGetCursorPos(), which asks the X server where the pointer is now and loses
    // the moves already queued behind the press (a quick drag turned half as far, or not at all).
    in.orbit.dragging = action == GLFW_PRESS;
    if (!in.orbit.pointer_seen) glfwGetCursorPos(w, &in.orbit.last_x, &in.orbit.last_y), in.orbit.pointer_seen = true;
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
    WindowInput& in = input_of(w);
    ++in.events;
    Orbit& o = in.orbit;
    if (o.dragging) {
      o.azimuth -= float(x - o.last_x) * kDragDegreesPerPixel;
      o.elevation = std::clamp(o.elevation + float(y - o.last_y) * kDragDegreesPerPixel, -85.0f, 85.0f);
      o.changed = true;
    }
    o.last_x = x, o.last_y = y, o.pointer_seen = true;
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
    WindowInput& in = input_of(w);
    ++in.events;
    if (ImGui::GetIO().WantCaptureMouse) return;
    in.orbit.distance = std::clamp(in.orbit.distance * float(std::pow(0.9, dy)), 0.25f, 20.0f);
    in.orbit.changed = true;
  });
  glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int) { ++input_of(w).events; });
  glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int) { ++input_of(w).events; });
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { ++input_of(w).events; });
  glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { ++input_of(w).events; });
}

}  // namespace inkwire
