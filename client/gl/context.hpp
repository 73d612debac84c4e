#pragma once
// One interface for every place GL can draw: an OSMesa off-screen buffer (headless, the
// default for tools and CI) or a GLFW window. Renderers never know which one they have.
#include <memory>
#include <string>

#include <glm/vec2.hpp>

namespace inkwire {

class Context {
 public:
  virtual ~Context() = default;
  // Makes this context current on the calling thread and loads GL entry points from it.
  virtual void make_current() = 0;
  virtual std::string backend() const = 0;
  // Size of the default framebuffer (window client area or off-screen buffer), in pixels.
  virtual glm::ivec2 framebuffer_size() const = 0;
  // Window backends present the default framebuffer and report the user closing them.
  virtual void present() {}
  virtual bool should_close() const { return false; }
  // The GLFWwindow of a window backend (for input callbacks and UI), null off-screen.
  virtual void* native_window() const { return nullptr; }

  std::string gl_renderer() const;  // GL_RENDERER of the current context
  std::string gl_version() const;   // GL_VERSION of the current context
};

// Off-screen GL 4.5 core context. `backend` is "osmesa" (the default), "egl" (EGL surfaceless,
// for Mesa builds without OSMesa) or "auto" (OSMesa, else EGL). Throws inkwire::Error when it
// cannot be made. Off-screen contexts draw into Canvas framebuffers.
std::unique_ptr<Context> create_offscreen_context(int width, int height, const std::string& backend = "osmesa");
std::unique_ptr<Context> create_osmesa_context(int width, int height);
std::unique_ptr<Context> create_egl_context(int width, int height);

// A GLFW window with a GL 4.5 core context (not forward-compatible, so wide lines work).
// `visible` false gives a hidden window; a visible one waits for the display's refresh when it
// presents (vsync). `samples` > 1 asks for a multisampled window (antialiasing), falling back
// to none when the driver offers none. Throws inkwire::Error when no display is available.
std::unique_ptr<Context> create_window_context(int width, int height, const std::string& title, bool visible = true, int samples = 1);

// True when a window system is reachable (DISPLAY or WAYLAND_DISPLAY set and GLFW can start).
bool window_system_available();

}  // namespace inkwire
