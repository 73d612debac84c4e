// The browser's renderer: the native client's scene drawing (client/render) compiled to
// WebAssembly, behind a small interface the page's JavaScript calls (SPEC W5). JavaScript keeps
// the session (WebSocket, assets, the panel); this module draws the session's model in its style
// from its camera and pose, exactly as the native client's SessionView does.
#include <emscripten/bind.h>

#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "client/gl/gl.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/scene_object.hpp"
#include "client/render/styles.hpp"
#include "client/web/module/module_class.hpp"
#include "common/camera.hpp"
#include "common/error.hpp"
#include "common/glb_mesh.hpp"

namespace inkwire {
namespace {

using json = nlohmann::json;

json param_json(const ParamSpec& p) {
  json j = {{"name", p.name}, {"type", to_string(p.type)}, {"default", p.default_value}, {"help", p.help}};
  if (p.type == ParamType::Float || p.type == ParamType::Int) j["min"] = p.min, j["max"] = p.max;
  if (!p.choices.empty()) j["choices"] = p.choices;
  if (p.names_file) j["file"] = true;  // a path on the machine that draws: the browser cannot read it
  return j;
}


}  // namespace

// One <inkwire-scene>'s picture: its WebGL2 context, the session's object, style and camera.
// Every call that can fail returns "" or a one-line reason; nothing throws into JavaScript.
class SceneView {
 public:
  explicit SceneView(const std::string& canvas_selector) : canvas_(canvas_selector) {}
  std::string error() const { return canvas_.error(); }

  // The session's model, a GLB (the server sends every mesh as one), at `address` in the
  // module's memory.
  std::string load_model(uintptr_t address, size_t size, const std::string& name) {
    return guarded([&] {
      const std::span<const uint8_t> bytes(reinterpret_cast<const uint8_t*>(address), size);
      Mesh mesh = read_glb_mesh(bytes, name);
      normalise(mesh, kSceneDiagonal);
      object_.emplace(make_scene_object(std::move(mesh)));
      if (renderer_) renderer_->prepare(*object_);
    });
  }

  // The session's style: `settings_json` a JSON list of "KEY=VALUE". A refused style keeps the
  // one drawn before (as the native client does) and says why.
  std::string set_style(const std::string& name, const std::string& settings_json) {
    return guarded([&] {
      const std::vector<std::string> settings = settings_of(settings_json);
      auto renderer = make_renderer(name, settings);
      backdrop_.emplace(BackdropSpec::parse(default_backdrop(name, settings)));
      if (object_) renderer->prepare(*object_);
      renderer_ = std::move(renderer);
      redraw_hz_ = style_redraw_hz(name);
    });
  }

  void set_camera(float px, float py, float pz, float tx, float ty, float tz, float ux, float uy, float uz, float fov) {
    camera_ = scene_camera({px, py, pz}, {tx, ty, tz}, {ux, uy, uz}, fov);
  }
  void set_object_pose(float qx, float qy, float qz, float qw, float tx, float ty, float tz, float scale) {
    model_ = pose_matrix({tx, ty, tz}, glm::quat(qw, qx, qy, qz), scale);
  }

  // One frame at `time_seconds` of animation time into the canvas's drawing buffer.
  std::string draw(double time_seconds) {
    return guarded([&] {
      const glm::ivec2 size = canvas_.begin_frame();
      if (!backdrop_) backdrop_.emplace(BackdropSpec::parse("paper"));
      backdrop_->draw();
      if (!object_ || !renderer_) return;
      renderer_->draw(scene_frame(size, camera_, model_, time_seconds, frame_++, &*backdrop_));
    });
  }
  double redraw_hz() const { return redraw_hz_; }

 private:
  ModuleCanvas canvas_;
  std::optional<SceneObject> object_;
  std::unique_ptr<Renderer> renderer_;
  std::optional<Backdrop> backdrop_;
  Camera camera_ = scene_orbit_camera(30, 20, 1.4f);
  glm::mat4 model_{1.0f};
  double redraw_hz_ = 0.0;
  long frame_ = 0;
};

// Every style the native client draws, as the browser draws them too: {"styles": [{name,
// summary}]}. A style's parameters: style_params_json().
std::string styles_json() {
  json list = json::array();
  for (const StyleInfo& s : styles()) list.push_back({{"name", s.name}, {"summary", s.summary}});
  return json{{"styles", list}}.dump();
}

// The parameters of a style or joined style ("hatching+sketch-pencil"), or {"error": reason}.
std::string style_params_json(const std::string& name) {
  try {
    json params = json::array();
    for (const ParamSpec& p : style_param_specs(name)) params.push_back(param_json(p));
    return params.dump();
  } catch (const Error& e) {
    return json{{"error", e.what()}}.dump();
  }
}

// The camera pose of an orbit (degrees, distance in scene diagonals) and back: what dragging in
// the native window sends.
std::string orbit_pose_json(float azimuth, float elevation, float distance) {
  const Camera c = scene_orbit_camera(azimuth, elevation, distance);
  return json{{"position", {c.position.x, c.position.y, c.position.z}},
              {"target", {c.target.x, c.target.y, c.target.z}},
              {"up", {c.up.x, c.up.y, c.up.z}},
              {"fov", c.fov_y_degrees}}
      .dump();
}
std::string orbit_of_json(float px, float py, float pz, float tx, float ty, float tz) {
  const SceneOrbit o = scene_orbit_of({px, py, pz}, {tx, ty, tz});
  return json{{"azimuth", o.azimuth}, {"elevation", o.elevation}, {"distance", o.distance}}.dump();
}

}  // namespace inkwire

EMSCRIPTEN_BINDINGS(inkwire_scene) {
  using namespace emscripten;
  using inkwire::SceneView;
  class_<SceneView>("SceneView")
      .constructor<std::string>()
      .function("error", &SceneView::error)
      .function("loadModel", &SceneView::load_model)
      .function("setStyle", &SceneView::set_style)
      .function("setCamera", &SceneView::set_camera)
      .function("setObjectPose", &SceneView::set_object_pose)
      .function("draw", &SceneView::draw)
      .function("redrawHz", &SceneView::redraw_hz);
  function("stylesJson", &inkwire::styles_json);
  function("styleParamsJson", &inkwire::style_params_json);
  function("orbitPoseJson", &inkwire::orbit_pose_json);
  function("orbitOfJson", &inkwire::orbit_of_json);
}
