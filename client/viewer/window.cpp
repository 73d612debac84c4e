// The interactive client: drag to orbit, wheel to zoom, Tab / arrows to switch styles, and a
// parameter panel (Dear ImGui). Every change is sent to the session, so all its clients follow.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "client/gl/gl.hpp"  // before GLFW, which must not pull in the system GL header
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glm/trigonometric.hpp>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "client/gl/context.hpp"
#include "client/render/styles.hpp"
#include "client/viewer/session_sync.hpp"
#include "client/viewer/viewer.hpp"
#include "common/error.hpp"

namespace inkwire {
namespace {

// The user's orbit, kept as angles so dragging never rolls the camera.
struct Orbit {
  float azimuth = 30, elevation = 20, distance = 1.4f;
  bool dragging = false;
  int photo_step = 0;  // arrow keys pressed since the last frame, in a product turntable (+1 right)
  double last_x = 0, last_y = 0;
  bool changed = false;

  void from(const protocol::CameraPose& pose) {
    const glm::vec3 d = pose.position - pose.target;
    distance = glm::length(d) / kSceneDiagonal;
    elevation = glm::degrees(std::asin(std::clamp(d.y / std::max(glm::length(d), 1e-6f), -1.0f, 1.0f)));
    azimuth = glm::degrees(std::atan2(d.x, d.z));
  }
};

// A let-go drag keeps turning and slows down, as a physical turntable does.
struct Inertia {
  float velocity = 0.0f;  // degrees per second
  float last_azimuth = 0.0f;
  bool was_dragging = false;

  void follow(Orbit& orbit, double dt) {
    if (dt <= 0.0) return;
    if (orbit.dragging) {
      const float v = float((orbit.azimuth - last_azimuth) / dt);
      velocity = was_dragging ? 0.7f * velocity + 0.3f * v : 0.0f;
    } else if (std::abs(velocity) > 2.0f) {
      orbit.azimuth += velocity * float(dt);
      velocity *= float(std::exp(-dt / 0.4));
    } else {
      velocity = 0.0f;
    }
    was_dragging = orbit.dragging;
    last_azimuth = orbit.azimuth;
  }
  void stop() { velocity = 0.0f; }
};

Orbit* orbit_of(GLFWwindow* w) { return static_cast<Orbit*>(glfwGetWindowUserPointer(w)); }

void install_orbit_callbacks(GLFWwindow* window) {
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    if (button != GLFW_MOUSE_BUTTON_LEFT || ImGui::GetIO().WantCaptureMouse) return;
    Orbit* o = orbit_of(w);
    o->dragging = action == GLFW_PRESS;
    glfwGetCursorPos(w, &o->last_x, &o->last_y);
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
    Orbit* o = orbit_of(w);
    if (!o->dragging) return;
    o->azimuth -= float(x - o->last_x) * 0.4f;
    o->elevation = std::clamp(o->elevation + float(y - o->last_y) * 0.4f, -85.0f, 85.0f);
    o->last_x = x, o->last_y = y;
    o->changed = true;
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
    if (ImGui::GetIO().WantCaptureMouse) return;
    Orbit* o = orbit_of(w);
    o->distance = std::clamp(o->distance * float(std::pow(0.9, dy)), 0.25f, 20.0f);
    o->changed = true;
  });
}

// Settings as a map over the style's defaults, so the panel shows every parameter's value.
std::map<std::string, std::string> settings_of(const protocol::StyleChange& style, const std::vector<ParamSpec>& specs) {
  std::map<std::string, std::string> values;
  for (const ParamSpec& p : specs) values[p.name] = p.default_value;
  for (const std::string& s : style.settings) {
    const size_t eq = s.find('=');
    values[s.substr(0, eq)] = s.substr(eq + 1);
  }
  return values;
}

// One widget per parameter; true when the user changed one.
bool parameter_panel(const std::vector<ParamSpec>& specs, std::map<std::string, std::string>& values) {
  bool changed = false;
  for (const ParamSpec& p : specs) {
    std::string& v = values[p.name];
    ImGui::PushID(p.name.c_str());
    switch (p.type) {
      case ParamType::Float: {
        float f = std::strtof(v.c_str(), nullptr);
        if (ImGui::SliderFloat(p.name.c_str(), &f, float(p.min), float(p.max))) v = std::to_string(f), changed = true;
        break;
      }
      case ParamType::Int: {
        int i = std::atoi(v.c_str());
        if (ImGui::SliderInt(p.name.c_str(), &i, int(p.min), int(std::min(p.max, 1e6)))) v = std::to_string(i), changed = true;
        break;
      }
      case ParamType::Bool: {
        bool b = v == "true" || v == "1" || v == "on";
        if (ImGui::Checkbox(p.name.c_str(), &b)) v = b ? "true" : "false", changed = true;
        break;
      }
      case ParamType::Choice:
        if (ImGui::BeginCombo(p.name.c_str(), v.c_str())) {
          for (const std::string& c : p.choices)
            if (ImGui::Selectable(c.c_str(), c == v)) v = c, changed = true;
          ImGui::EndCombo();
        }
        break;
      default:
        ImGui::Text("%s = %s", p.name.c_str(), v.c_str());
    }
    if (ImGui::IsItemHovered() && !p.help.empty()) ImGui::SetTooltip("%s", p.help.c_str());
    ImGui::PopID();
  }
  return changed;
}

protocol::StyleChange style_change(const std::string& renderer, const std::map<std::string, std::string>& values) {
  protocol::StyleChange change{.renderer = renderer, .settings = {}};
  for (const auto& [key, value] : values) change.settings.push_back(key + "=" + value);
  return change;
}

}  // namespace

int run_window(SessionClient& client, AssetCache& cache, const ViewerOptions& o) {
  auto context = create_window_context(o.size.x, o.size.y, "Inkwire - " + client.state().session, true);
  auto* window = static_cast<GLFWwindow*>(context->native_window());
  Orbit orbit;
  orbit.from(client.state().camera);
  glfwSetWindowUserPointer(window, &orbit);
  install_orbit_callbacks(window);
  // Keys from GLFW itself: the packaged ImGui (1.86) does not report them to IsKeyPressed.
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    if ((action != GLFW_PRESS && action != GLFW_REPEAT) || ImGui::GetIO().WantCaptureKeyboard) return;
    if (key == GLFW_KEY_RIGHT) ++orbit_of(w)->photo_step;
    if (key == GLFW_KEY_LEFT) --orbit_of(w)->photo_step;
  });

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window, true);  // chains to the callbacks above
  ImGui_ImplOpenGL3_Init("#version 450 core");

  SessionSync sync(client, cache);
  const auto& all = styles();
  uint32_t sequence = 1;
  long frame = 0;
  std::string specs_style;        // the style whose parameters `specs` lists
  std::vector<ParamSpec> specs;
  const double start = glfwGetTime();
  // A product's view is the visitor's own (nothing is sent): dragging turns it and lets go with
  // inertia, the wheel zooms, the arrow keys step one photo.
  Inertia inertia;
  bool turntable_started = false;
  double last_time = glfwGetTime();
  while (!context->should_close() && client.connected()) {
    const double now = glfwGetTime(), dt = std::min(now - last_time, 0.1);
    last_time = now;
    const bool polled = sync.poll();
    TurntableView* product = sync.view().turntable();
    if (product) {
      if (!turntable_started) orbit = Orbit{.azimuth = 0, .elevation = 0, .distance = 1.0f}, turntable_started = true;
      if (!product->all_round()) orbit.elevation = 0;  // the photos go round one ring
      inertia.follow(orbit, dt);
      if (orbit.photo_step != 0) {
        const int n = product->samples();
        const int next = ((product->nearest_sample(sync.view().orbit()) + orbit.photo_step) % n + n) % n;
        orbit.azimuth = product->sample_angles(next).x;
        orbit.photo_step = 0;
        inertia.stop();
      }
      sync.view().orbit() = {.azimuth = orbit.azimuth, .elevation = orbit.elevation, .zoom = 1.0f / orbit.distance};
      orbit.changed = false;
    } else {
      if (polled && !orbit.dragging) orbit.from(sync.state().camera);
      if (orbit.changed) {
        client.send(orbit_pose(orbit.azimuth, orbit.elevation, orbit.distance, sequence++));
        orbit.changed = false;
      }
    }
    // Tab / Right: next style, Left: previous.
    const std::string current = sync.state().style.renderer;
    auto it = std::find_if(all.begin(), all.end(), [&](const StyleInfo& s) { return s.name == current; });
    const int index = it == all.end() ? 0 : int(it - all.begin()), n = int(all.size());
    int step = 0;
    if (!product && !ImGui::GetIO().WantCaptureKeyboard) {
      if (ImGui::IsKeyPressed(ImGuiKey_Tab) || ImGui::IsKeyPressed(ImGuiKey_RightArrow)) step = 1;
      if (ImGui::IsKeyPressed(ImGuiKey_LeftArrow)) step = -1;
    }
    if (step) client.send(protocol::StyleChange{.renderer = all[size_t((index + step + n) % n)].name, .settings = {}});

    const glm::ivec2 size = context->framebuffer_size();
    gl::glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::glViewport(0, 0, size.x, size.y);
    sync.view().draw(size, glfwGetTime() - start, frame++);

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.8f);
    ImGui::Begin("Session", nullptr, ImGuiWindowFlags_AlwaysAutoResize);  // fits each style's parameters
    ImGui::Text("%s  revision %u  sent %llu B  received %llu B", sync.state().session.c_str(), sync.view().revision(),
                (unsigned long long)client.bytes_sent(), (unsigned long long)client.bytes_received());
    if (product) {
      // Photos arrive nearest the view first; the view tweens wherever a pair is complete.
      char label[64];
      std::snprintf(label, sizeof label, "photos %d / %d", product->samples_loaded(), product->samples());
      if (!product->complete()) ImGui::ProgressBar(float(product->samples_loaded()) / float(std::max(product->samples(), 1)), ImVec2(240, 0), label);
      else ImGui::Text("%s, drag to turn, wheel to zoom, arrows step one photo", label);
    } else if (ImGui::BeginCombo("style", current.c_str())) {
      for (const StyleInfo& s : all)
        if (ImGui::Selectable(s.name.c_str(), s.name == current)) client.send(protocol::StyleChange{.renderer = s.name, .settings = {}});
      ImGui::EndCombo();
    }
    if (current != specs_style) {  // joined styles ('hatching+sketch-pencil') too; none for an unknown name
      specs_style = current;
      try {
        specs = style_param_specs(current);
      } catch (const Error&) {
        specs.clear();
      }
    }
    // Folded at first, so the picture is not hidden behind a long list.
    if (!product && !specs.empty() && ImGui::CollapsingHeader("parameters")) {
      auto values = settings_of(sync.state().style, specs);
      if (parameter_panel(specs, values)) client.send(style_change(current, values));
    }
    if (!sync.view().error().empty()) ImGui::TextColored(ImVec4(0.8f, 0.1f, 0.1f, 1), "%s", sync.view().error().c_str());
    ImGui::End();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    context->present();
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return 0;
}

}  // namespace inkwire
