#include "client/gl/context.hpp"

#include "client/gl/gl.hpp"

namespace inkwire {

std::string Context::gl_renderer() const { return reinterpret_cast<const char*>(gl::glGetString(GL_RENDERER)); }
std::string Context::gl_version() const { return reinterpret_cast<const char*>(gl::glGetString(GL_VERSION)); }

}  // namespace inkwire
