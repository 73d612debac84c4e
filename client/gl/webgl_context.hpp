#pragma once
// The browser's GL: a WebGL2 context on a page's <canvas> (the WebAssembly build only). Renderers
// draw into its default framebuffer as into a window's.
#include <memory>
#include <string>

#include "client/gl/context.hpp"

namespace inkwire {

// `canvas_selector` as the page knows it (e.g. "#inkwire-scene-1"). Throws inkwire::Error with a
// one-line reason when the browser gives no WebGL2 context.
std::unique_ptr<Context> create_webgl_context(const std::string& canvas_selector);

}  // namespace inkwire
