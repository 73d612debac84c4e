// The WebGL2 backend (WebAssembly build only): the GL entry points come from Emscripten's WebGL
// bindings through the same loader as every native backend, so a function WebGL2 lacks fails at
// start with its name instead of at its first call.
#include "client/gl/webgl_context.hpp"

#include <emscripten/html5.h>
#include <emscripten/html5_webgl.h>

#include "client/gl/loader.hpp"
#include "common/error.hpp"

namespace inkwire {
namespace {

void* webgl_proc(const char* name) { return emscripten_webgl_get_proc_address(name); }

class WebglContext final : public Context {
 public:
  explicit WebglContext(const std::string& selector) : selector_(selector) {
    EmscriptenWebGLContextAttributes attributes;
    emscripten_webgl_init_context_attributes(&attributes);
    attributes.majorVersion = 2;
    attributes.minorVersion = 0;
    attributes.alpha = false;      // the backdrop is opaque, as in a window
    attributes.depth = true;
    attributes.stencil = true;
    attributes.antialias = false;  // lines fade by coverage; as the native clients draw
    attributes.preserveDrawingBuffer = true;  // the page may read the picture back (tests, snapshots)
    context_ = emscripten_webgl_create_context(selector.c_str(), &attributes);
    if (context_ <= 0) throw Error("this browser gives no WebGL2 context (error " + std::to_string(int(context_)) + ")");
    make_current();
  }
  ~WebglContext() override { emscripten_webgl_destroy_context(context_); }

  void make_current() override {
    if (emscripten_webgl_make_context_current(context_) != EMSCRIPTEN_RESULT_SUCCESS) throw Error("cannot make the WebGL2 context current");
    gl::load_functions(webgl_proc);
  }
  std::string backend() const override { return "webgl2"; }
  glm::ivec2 framebuffer_size() const override {
    int width = 0, height = 0;
    emscripten_webgl_get_drawing_buffer_size(context_, &width, &height);
    return {width, height};
  }

 private:
  std::string selector_;
  EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context_ = 0;
};

}  // namespace

std::unique_ptr<Context> create_webgl_context(const std::string& canvas_selector) { return std::make_unique<WebglContext>(canvas_selector); }

}  // namespace inkwire
