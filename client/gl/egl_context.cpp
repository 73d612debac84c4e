// The EGL surfaceless backend: a second headless path, for Mesa builds without OSMesa (dropped
// in Mesa 25.1). No window and no pbuffer: everything draws into our own framebuffers.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>

#include "client/gl/context.hpp"
#include "client/gl/loader.hpp"
#include "common/error.hpp"

namespace inkwire {
namespace {

void* egl_proc(const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p; p = std::strstr(p + n, name))
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

class EglContext final : public Context {
 public:
  EglContext(int width, int height) : width_(width), height_(height) {
    const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!has_extension(client_ext, "EGL_MESA_platform_surfaceless"))
      throw Error("EGL: the surfaceless platform (EGL_MESA_platform_surfaceless) is not available");
    auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) throw Error("EGL: eglGetPlatformDisplayEXT is missing");
    display_ = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, nullptr, nullptr))
      throw Error("EGL: could not initialise the surfaceless display");
    const char* ext = eglQueryString(display_, EGL_EXTENSIONS);
    if (!has_extension(ext, "EGL_KHR_surfaceless_context") || !has_extension(ext, "EGL_KHR_no_config_context")) {
      eglTerminate(display_);
      throw Error("EGL: surfaceless contexts without a config are not supported by this driver");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
      eglTerminate(display_);
      throw Error("EGL: desktop OpenGL is not available");
    }
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (context_ == EGL_NO_CONTEXT) {
      eglTerminate(display_);
      throw Error("EGL: could not create a GL 4.5 core context");
    }
    make_current();
  }
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

  void make_current() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) throw Error("EGL: could not make the context current");
    gl::load_functions(egl_proc);
  }
  std::string backend() const override { return "egl"; }
  // There is no default framebuffer: report the size asked for, which canvases use.
  glm::ivec2 framebuffer_size() const override { return {width_, height_}; }

 private:
  int width_, height_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> create_egl_context(int width, int height) { return std::make_unique<EglContext>(width, height); }

}  // namespace inkwire
