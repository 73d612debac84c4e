#include "client/viewer/frame_log.hpp"

#include <chrono>

namespace inkwire {

nlohmann::json frame_log_line(SessionSync& sync, const SessionClient& client, long frame) {
  const auto now_us = std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
  nlohmann::json line = {{"frame", frame}, {"revision", sync.view().revision()}, {"style", sync.view().style()}, {"monotonic_us", now_us}};
  if (const TurntableView* t = sync.view().turntable())
    line["product"] = {{"azimuth", sync.view().orbit().azimuth}, {"elevation", sync.view().orbit().elevation},
                       {"zoom", sync.view().orbit().zoom}, {"samples_loaded", t->samples_loaded()},
                       {"cells_loaded", t->cells_loaded()}, {"finer_loaded", t->finer_loaded()},
                       {"finer_in_view", t->finer_in_view()}, {"bytes_sent", client.bytes_sent()},
                       {"bytes_received", client.bytes_received()}};
  if (const protocol::Permissions p = client.permissions(); !p.refused.empty()) {
    line["may_not"] = nlohmann::json::array();
    for (const auto& r : p.refused) line["may_not"].push_back(protocol::name_of(r.change));
  }
  if (client.refusals() > 0) line["refused"] = {{"count", client.refusals()}, {"reason", client.refusal()}};
  // A call's members as the page's element exposes them (docs/calls.md): name, speaking, expression.
  if (const CallGrid& call = sync.view().call(); !call.empty()) {
    nlohmann::json members = nlohmann::json::array();
    for (const CallGrid::Tile& t : call.tiles()) {
      if (t.member == 0) continue;
      const auto shown = call.expression(t.member);
      nlohmann::json member = {{"name", t.name}, {"speaking", t.speaking}, {"expression", name_of(shown ? shown->expression : Expression::Neutral)},
                               {"you", t.you}, {"camera", t.camera}, {"microphone", t.microphone}, {"face_found", t.face_found}};
      // The face's layers and pose it is drawn to (SPEC F20-F22).
      if (const auto face = call.face(t.member))
        member["face"] = {{"pose", {face->pose.yaw, face->pose.pitch, face->pose.roll}},
                          {"eyes", {face->layers.eye_left, face->layers.eye_right}},
                          {"layers", {name_of(face->layers.expression.expression), name_of(face->layers.mouth.expression)}}};
      members.push_back(member);
    }
    line["members"] = members;
  }
  if (const auto expression = sync.view().expression())
    line["expression"] = {{"name", name_of(expression->expression)}, {"intensity", expression->intensity}};
  if (const int painted = sync.view().painted_frames(); painted > 0) line["painted_frames"] = painted;
  return line;
}

}  // namespace inkwire
