#pragma once
// Loading GL entry points from the current context. Kept apart from gl.hpp so context backends
// can include their platform headers (which declare gl* prototypes of their own) without it.
namespace inkwire::gl {

using GetProcAddress = void* (*)(const char* name);

// Fills every pointer in gl.hpp from `get`. Throws inkwire::Error naming the first missing one.
void load_functions(GetProcAddress get);

}  // namespace inkwire::gl
