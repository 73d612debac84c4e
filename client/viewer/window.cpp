// The interactive client: drag to orbit, wheel to zoom, Tab / Shift-Tab to switch styles, arrows
// to step the view, and a side panel (Dear ImGui) with the style and its parameters. Every change
// is sent to the session, so all its clients follow. The window draws only when something
// changed (input, the session, a style that animates), so an idle window costs next to nothing.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "client/gl/gl.hpp"  // before GLFW, which must not pull in the system GL header
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "client/call/call_captions.hpp"
#include "client/call/publisher.hpp"
#include "client/call/speaker.hpp"
#include "client/gl/context.hpp"
#include "client/render/styles.hpp"
#include "client/viewer/frame_log.hpp"
#include "client/viewer/session_sync.hpp"
#include "client/viewer/style_panel.hpp"
#include "client/viewer/viewer.hpp"
#include "client/viewer/window_input.hpp"
#include "common/error.hpp"

namespace inkwire {
namespace {

constexpr float kStepDegrees = 15.0f;       // an arrow key turns the scene this far
constexpr double kIdlePollSeconds = 0.05;   // an idle window still takes the session's news this often
constexpr int kFramesAfterInput = 3;        // ImGui settles hover and click state over a few frames
constexpr float kPanelWidth = 210.0f;       // the panel's width until the user drags it wider

// Where ImGui keeps the panel's width and whether it is folded, between runs.
std::string panel_settings_file() {
  const char* config = std::getenv("XDG_CONFIG_HOME");
  const char* home = std::getenv("HOME");
  if ((!config || !*config) && (!home || !*home)) return "";
  const std::filesystem::path dir = config && *config ? std::filesystem::path(config) / "inkwire"
                                                      : std::filesystem::path(home) / ".config" / "inkwire";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  return ec ? "" : (dir / "client-window.ini").string();
}

// The panel docked to the window's right edge, full height, as wide as the user left it.
struct PanelRect {
  float x = 0, width = 0, height = 0;
  bool folded = false;
  // The width the picture must leave free.
  float covered() const { return folded ? 0.0f : width; }
};

PanelRect begin_panel(glm::ivec2 window) {
  const float w = float(window.x), h = float(window.y);
  ImGui::SetNextWindowPos(ImVec2(w, 0), ImGuiCond_Always, ImVec2(1, 0));
  ImGui::SetNextWindowSize(ImVec2(std::min(kPanelWidth, w * 0.33f), h), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(140.0f, w), h), ImVec2(std::max(140.0f, w * 0.6f), h));
  ImGui::SetNextWindowBgAlpha(1.0f);  // docked: nothing of the picture is under it
  const bool open = ImGui::Begin("Inkwire", nullptr, ImGuiWindowFlags_NoMove);
  return {.x = ImGui::GetWindowPos().x, .width = ImGui::GetWindowSize().x, .height = ImGui::GetWindowSize().y, .folded = !open};
}

}  // namespace

int run_window(SessionClient& client, AssetCache& cache, const ViewerOptions& o) {
  auto context = create_window_context(o.size.x, o.size.y, "Inkwire - " + client.state().session, true, o.msaa);
  auto* window = static_cast<GLFWwindow*>(context->native_window());
  WindowInput input;
  input.orbit.from(client.state().camera);
  input.attach(window);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  static std::string settings_file;  // ImGui keeps the pointer
  settings_file = panel_settings_file();
  ImGui::GetIO().IniFilename = settings_file.empty() ? nullptr : settings_file.c_str();
  ImGui_ImplGlfw_InitForOpenGL(window, true);  // chains to the callbacks above
  ImGui_ImplOpenGL3_Init("#version 450 core");

  std::ofstream log;
  if (!o.frame_log.empty()) log.open(o.frame_log);
  SessionSync sync(client, cache);
  StylePanel panel;
  PanelRect panel_rect;
  uint32_t sequence = 1;
  long frame = 0, seen_events = -1;
  int settle = 0;
  const double start = glfwGetTime();
  double last_time = start, next_animation = start;
  // A product's view is the visitor's own (nothing is sent): dragging turns it and lets go with
  // inertia, the wheel zooms, the arrow keys step one photo.
  Inertia inertia;
  bool turntable_started = false;
  // Presenter mode (off unless asked): a presenter's view goes to the session as object poses,
  // a follower shows the newest of them.
  bool present = o.present, follow = o.follow;
  TurntableOrbit presented{.zoom = 0.0f};  // none sent yet
  protocol::ObjectPose followed{.sequence = ~0u};  // none shown yet
  Orbit& orbit = input.orbit;
  uint64_t refusals = 0;  // the server's refusals seen so far (a change this member may not make)
  // A call's sound, when the session is one: opened once, fed what is due each frame.
  std::unique_ptr<Speaker> speaker;
  if (client.state().kind == protocol::SessionKind::Conference) speaker = std::make_unique<Speaker>();
  while (!context->should_close() && (client.connected() || client.rejoining())) {
    const double now = glfwGetTime(), dt = std::min(now - last_time, 0.1);
    last_time = now;
    bool dirty = sync.poll();
    const std::vector<float> due = sync.audio().take(std::chrono::steady_clock::now());
    if (speaker) speaker->play(due);
    if (o.publisher && (input.toggle_mute || input.toggle_camera)) {
      if (input.toggle_mute) o.publisher->set_muted(!o.publisher->muted());
      if (input.toggle_camera) o.publisher->set_camera_off(!o.publisher->camera_off());
      dirty = true;
    }
    if (client.refusals() != refusals) {
      // Refused: the session's value came back; stop presenting what nobody will see.
      refusals = client.refusals();
      present = false;
      dirty = true;
    }
    // What the server will refuse this member (said on joining): those controls stay still here
    // instead of being undone, and the panel says why.
    const protocol::Permissions permissions = client.permissions();
    const auto refusal_of = [&](protocol::MessageType change) {
      for (const auto& r : permissions.refused)
        if (r.change == change) return r.reason;
      return std::string();
    };
    const std::string camera_refused = refusal_of(protocol::MessageType::CameraPose), style_refused = refusal_of(protocol::MessageType::StyleChange);
    TurntableView* product = sync.view().turntable();
    if (product) {
      if (!turntable_started) orbit = Orbit{.azimuth = 0, .elevation = 0, .distance = 1.0f}, turntable_started = true;
      inertia.follow(orbit, dt);
      if (input.view_step_y != 0) {
        orbit.elevation = product->row_elevation(orbit.elevation, input.view_step_y);
        inertia.stop();
        dirty = true;
      }
      // Up and down as far as there are rows of photos (one ring: its own height).
      const glm::vec2 heights = product->elevation_range();
      orbit.elevation = std::clamp(orbit.elevation, heights.x, heights.y);
      if (input.view_step_x != 0) {
        const int n = product->samples();
        const int next = ((product->nearest_sample(sync.view().orbit()) + input.view_step_x) % n + n) % n;
        orbit.azimuth = product->sample_angles(next).x;
        inertia.stop();
        dirty = true;
      }
      if (input.toggle_present) present = !present, dirty = true;
      if (input.toggle_follow) follow = !follow, followed.sequence = ~0u, dirty = true;
      // The presenter's newest view replaces this one; the visitor may turn it until the next.
      if (follow && !(sync.state().object == followed)) {
        followed = sync.state().object;
        const TurntableOrbit shared = TurntableOrbit::from_pose(followed);
        orbit.azimuth = shared.azimuth, orbit.elevation = shared.elevation, orbit.distance = 1.0f / shared.zoom;
        inertia.stop();
        dirty = true;
      }
      // The wheel moves the orbit's distance as in a scene; a product zooms within its own range.
      orbit.distance = 1.0f / std::clamp(1.0f / orbit.distance, TurntableOrbit::kMinZoom, TurntableOrbit::kMaxZoom);
      sync.view().orbit() = {.azimuth = orbit.azimuth, .elevation = orbit.elevation, .zoom = 1.0f / orbit.distance};
      if (present && !(sync.view().orbit() == presented)) {
        presented = sync.view().orbit();
        client.send(presented.pose(sequence++));
      }
      dirty |= orbit.changed || inertia.moving() || !product->complete();
      orbit.changed = false;
    } else {
      if (input.view_step_x || input.view_step_y) {
        orbit.azimuth += kStepDegrees * float(input.view_step_x);
        orbit.elevation = std::clamp(orbit.elevation + kStepDegrees * float(input.view_step_y), -85.0f, 85.0f);
        orbit.changed = true;
      }
      if (!camera_refused.empty() && orbit.changed) orbit.from(sync.state().camera), orbit.changed = false;
      if (dirty && !orbit.dragging && !orbit.changed) orbit.from(sync.state().camera);
      if (orbit.changed) {
        client.send(orbit_pose(orbit.azimuth, orbit.elevation, orbit.distance, sequence++));
        orbit.changed = false;
        dirty = true;
      }
      if (input.style_step && style_refused.empty()) {
        const std::vector<std::string> names = style_names();
        const auto it = std::find(names.begin(), names.end(), sync.state().style.renderer);
        const int n = int(names.size()), index = it == names.end() ? 0 : int(it - names.begin());
        client.send(protocol::StyleChange{.renderer = names[size_t(((index + input.style_step) % n + n) % n)], .settings = {}});
      }
    }
    input.clear_steps();
    if (input.events != seen_events) seen_events = input.events, settle = kFramesAfterInput;
    // Styles that change a still picture (boiling lines, drifting brushes) redraw at their rate.
    double redraw_hz = 0.0;
    try {
      redraw_hz = style_redraw_hz(sync.state().style.renderer);
    } catch (const Error&) {
    }
    // A call changes as its members speak and move: drawn at the faces' rate.
    if (!sync.view().call().empty()) redraw_hz = std::max(redraw_hz, 30.0);
    if (redraw_hz > 0.0 && now >= next_animation) dirty = true, next_animation = std::max(next_animation + 1.0 / redraw_hz, now);
    if (!dirty && settle == 0) {
      double wait = kIdlePollSeconds;
      if (redraw_hz > 0.0) wait = std::clamp(next_animation - now, 0.0, wait);
      glfwWaitEventsTimeout(wait);
      continue;
    }
    settle = std::max(settle - 1, 0);

    // The picture fills the window left of the panel: the panel never hides the object.
    int window_w = 0, window_h = 0;
    glfwGetWindowSize(window, &window_w, &window_h);
    const glm::ivec2 size = context->framebuffer_size();
    const int picture_w = std::max(1, size.x - int(panel_rect.covered() * float(size.x) / float(std::max(window_w, 1))));
    gl::glBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl::glViewport(0, 0, size.x, size.y);
    gl::glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    gl::glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl::glViewport(0, 0, picture_w, size.y);
    sync.view().draw({picture_w, size.y}, glfwGetTime() - start, frame);

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    panel_rect = begin_panel({window_w, window_h});
    // Tab is the window's key for the next style: ImGui must not take it to focus a text field.
    ImGui::PushAllowKeyboardFocus(false);
    if (!panel_rect.folded) {
      ImGui::TextWrapped("%s, revision %u", sync.state().session.c_str(), sync.view().revision());
      ImGui::TextWrapped("sent %llu B, received %llu B", (unsigned long long)client.bytes_sent(), (unsigned long long)client.bytes_received());
      ImGui::Separator();
      if (!sync.view().call().empty()) {
        // A call: every member's tile, its name and state under it; this member's keys.
        for (const CallGrid::Tile& t : sync.view().call().tiles()) {
          const float to_window = float(window_w) / float(std::max(size.x, 1));
          ImGui::GetForegroundDrawList()->AddText(ImVec2(float(t.rect.x) * to_window, float(t.rect.y + t.rect.w + 3) * to_window),
                                                  t.speaking ? IM_COL32(90, 230, 120, 255) : IM_COL32(235, 235, 235, 255), caption_of(t).c_str());
        }
        if (speaker && !speaker->open()) ImGui::TextWrapped("%s", speaker->reason().c_str());
        if (o.publisher)
          ImGui::TextWrapped("M: %s. C: %s. Microphone %.0f dB.", o.publisher->muted() ? "unmute" : "mute",
                             o.publisher->camera_off() ? "camera on" : "camera off", o.publisher->level_db());
        else
          ImGui::TextWrapped("Listening: join with --camera and --microphone to be seen and heard.");
      }
      if (product) {
        // Photos arrive nearest the view first; the view tweens wherever a pair is complete.
        char label[64];
        std::snprintf(label, sizeof label, "photos %d / %d", product->samples_loaded(), product->samples());
        if (!product->complete()) ImGui::ProgressBar(float(product->samples_loaded()) / float(std::max(product->samples(), 1)), ImVec2(-1, 0), label);
        else ImGui::TextWrapped("%s. Drag to turn, wheel to zoom, arrows step one photo.", label);
        ImGui::TextWrapped("P: %s this view to the session. F: %s the presenter's view.", present ? "stop presenting" : "present",
                           follow ? "stop following" : "follow");
      } else {
        if (!camera_refused.empty()) ImGui::TextWrapped("%s.", camera_refused.c_str());
        else if (sync.view().call().empty()) ImGui::TextWrapped("Drag to orbit, wheel to zoom, Tab / Shift-Tab: style, arrows: view.");
        if (!style_refused.empty() && style_refused != camera_refused) ImGui::TextWrapped("%s.", style_refused.c_str());
        ImGui::BeginDisabled(!style_refused.empty());
        if (auto change = panel.draw(sync.state().style)) client.send(*change);
        ImGui::EndDisabled();
      }
      if (!sync.view().error().empty()) ImGui::TextColored(ImVec4(0.9f, 0.3f, 0.3f, 1), "%s", sync.view().error().c_str());
      if (refusals > 0) ImGui::TextColored(ImVec4(0.95f, 0.6f, 0.2f, 1), "Refused: %s", client.refusal().c_str());
    }
    ImGui::PopAllowKeyboardFocus();
    ImGui::End();
    ImGui::Render();
    gl::glViewport(0, 0, size.x, size.y);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    context->present();
    if (log) {
      nlohmann::json line = frame_log_line(sync, client, frame);
      line["window"] = {window_w, window_h};
      line["panel"] = {{"x", panel_rect.x}, {"width", panel_rect.width}, {"height", panel_rect.height},
                       {"folded", panel_rect.folded}};
      log << line.dump() << "\n" << std::flush;
    }
    ++frame;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return 0;
}

}  // namespace inkwire
