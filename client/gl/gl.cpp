#include "client/gl/gl.hpp"

#include <cstdio>
#include <string>

#include "common/error.hpp"

namespace inkwire::gl {

#define INKWIRE_GL_DEFINE(type, name) type name = nullptr;
INKWIRE_GL_FUNCTIONS(INKWIRE_GL_DEFINE)
#undef INKWIRE_GL_DEFINE

void load_functions(GetProcAddress get) {
#define INKWIRE_GL_LOAD(type, name)                                               \
  name = reinterpret_cast<type>(get(#name));                                      \
  if (!name) throw Error(std::string("OpenGL entry point ") + #name + " is missing");
  INKWIRE_GL_FUNCTIONS(INKWIRE_GL_LOAD)
#undef INKWIRE_GL_LOAD
}

void check_error(const char* where) {
  const GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  char code[16];
  std::snprintf(code, sizeof(code), "0x%04x", e);
  throw Error(std::string(where) + ": GL error " + code);
}

}  // namespace inkwire::gl
