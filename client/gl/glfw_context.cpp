// The GLFW window backend.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <mutex>

#include "client/gl/context.hpp"
#include "client/gl/loader.hpp"
#include "common/error.hpp"

namespace inkwire {
namespace {

void* glfw_proc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

bool init_glfw() {
  static std::once_flag once;
  static bool ok = false;
  std::call_once(once, [] {
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) return;
    glfwSetErrorCallback([](int, const char*) {});  // errors surface as null returns below
    ok = glfwInit() == GLFW_TRUE;
    if (ok) std::atexit(glfwTerminate);
  });
  return ok;
}

class GlfwContext final : public Context {
 public:
  GlfwContext(int width, int height, const std::string& title, bool visible, int samples) {
    if (!init_glfw()) throw Error("no window system: DISPLAY is not set or GLFW could not start");
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    // Not forward-compatible: forward-compatible contexts refuse line widths above 1.
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SAMPLES, samples > 1 ? samples : 0);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_ && samples > 1) {  // no multisampled visual: a plain window still serves
      glfwWindowHint(GLFW_SAMPLES, 0);
      window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    }
    if (!window_) throw Error("GLFW could not open a window with a GL 4.5 core context");
    make_current();
    if (visible) glfwSwapInterval(1);  // no more frames than the display shows
  }
  ~GlfwContext() override { glfwDestroyWindow(window_); }

  void make_current() override {
    glfwMakeContextCurrent(window_);
    gl::load_functions(glfw_proc);
  }
  std::string backend() const override { return "glfw"; }
  glm::ivec2 framebuffer_size() const override {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {w, h};
  }
  void present() override {
    glfwSwapBuffers(window_);
    glfwPollEvents();
  }
  bool should_close() const override { return glfwWindowShouldClose(window_); }
  void* native_window() const override { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace

bool window_system_available() { return init_glfw(); }

std::unique_ptr<Context> create_window_context(int width, int height, const std::string& title, bool visible, int samples) {
  return std::make_unique<GlfwContext>(width, height, title, visible, samples);
}

}  // namespace inkwire
