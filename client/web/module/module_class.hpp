#pragma once
// What every class the module gives JavaScript shares: its page's canvas, a call that never
// throws into the page (it returns "" or the one-line reason), and a style's settings as the page
// passes them.
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include "client/gl/gl.hpp"
#include "client/gl/webgl_context.hpp"
#include "common/error.hpp"

namespace inkwire {

// A page's <canvas> with its WebGL2 context, or the reason the browser gave none.
class ModuleCanvas {
 public:
  explicit ModuleCanvas(const std::string& selector) {
    try {
      context_ = create_webgl_context(selector);
    } catch (const Error& e) {
      error_ = e.what();
    }
  }
  const std::string& error() const { return error_; }
  // Binds the canvas's drawing buffer over its whole size, which it returns; throws the reason
  // there is no context.
  glm::ivec2 begin_frame() const {
    if (!context_) throw Error(error_);
    const glm::ivec2 size = context_->framebuffer_size();
    gl::glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::glViewport(0, 0, size.x, size.y);
    return size;
  }

 private:
  std::unique_ptr<Context> context_;
  std::string error_;
};

// Runs `action`; "" when it succeeded, else what went wrong, in one line.
template <class Action>
std::string guarded(Action action) {
  try {
    action();
    return "";
  } catch (const Error& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("unexpected: ") + e.what();
  }
}

// A JSON list of "KEY=VALUE" strings, as the session's style carries them.
inline std::vector<std::string> settings_of(const std::string& settings_json) {
  std::vector<std::string> settings;
  for (const auto& s : nlohmann::json::parse(settings_json)) settings.push_back(s.get<std::string>());
  return settings;
}

}  // namespace inkwire
