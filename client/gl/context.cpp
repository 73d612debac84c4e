#include "client/gl/context.hpp"

#include "client/gl/gl.hpp"
#include "common/error.hpp"

namespace inkwire {

std::unique_ptr<Context> create_offscreen_context(int width, int height, const std::string& backend) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw Error("off-screen size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1..16384");
  if (backend == "osmesa") return create_osmesa_context(width, height);
  if (backend == "egl") return create_egl_context(width, height);
  if (backend == "auto") {
    try {
      return create_osmesa_context(width, height);
    } catch (const Error&) {
      return create_egl_context(width, height);
    }
  }
  throw Error("GL backend '" + backend + "' is unknown (osmesa, egl, auto)");
}

std::string Context::gl_renderer() const { return reinterpret_cast<const char*>(gl::glGetString(GL_RENDERER)); }
std::string Context::gl_version() const { return reinterpret_cast<const char*>(gl::glGetString(GL_VERSION)); }

}  // namespace inkwire
