#include "server/web/metrics.hpp"

#include <filesystem>
#include <fstream>

#include "server/relay/relay.hpp"
#include "server/server.hpp"

namespace inkwire::server {
namespace {

class MetricsText {
 public:
  // One metric's HELP and TYPE lines, then its samples through sample().
  MetricsText& metric(const std::string& name, const char* type, const char* help) {
    text_ += "# HELP " + name + " " + help + "\n# TYPE " + name + " " + type + "\n";
    return *this;
  }
  template <class Number>
  MetricsText& sample(const std::string& name, Number value, const std::string& labels = "") {
    text_ += name + (labels.empty() ? "" : "{" + labels + "}") + " " + std::to_string(value) + "\n";
    return *this;
  }
  template <class Number>
  MetricsText& one(const std::string& name, const char* type, const char* help, Number value) {
    return metric(name, type, help).sample(name, value);
  }
  std::string take() { return std::move(text_); }

 private:
  std::string text_;
};

// What the kernel says of this process: resident memory (bytes) and threads, from
// /proc/self/status; open descriptors, from /proc/self/fd. Zero where /proc is not there.
struct ProcessFigures {
  double resident_bytes = 0, threads = 0, descriptors = 0;
};
ProcessFigures process_figures() {
  ProcessFigures f;
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmRSS:", 0) == 0) f.resident_bytes = std::stod(line.substr(6)) * 1024;  // kB
    if (line.rfind("Threads:", 0) == 0) f.threads = std::stod(line.substr(8));
  }
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator("/proc/self/fd", ec); !ec && it != std::filesystem::directory_iterator(); it.increment(ec))
    ++f.descriptors;
  return f;
}

}  // namespace

std::string metric_label(const std::string& value) {
  std::string out;
  for (const char c : value) {
    if (c == '\\' || c == '"') out += '\\', out += c;
    else if (c == '\n') out += "\\n";
    else out += c;
  }
  return out;
}

std::string metrics_text(Server& server) {
  const ServerCounters& c = server.counters();
  MetricsText m;
  m.one("inkwire_connections", "gauge", "Open client connections (TCP and WebSocket).", server.connection_count());
  m.metric("inkwire_connections_by_kind", "gauge", "Open client connections by transport, and whether they have joined a session.");
  for (const auto& [kind, count] : server.connections_by_kind())
    m.sample("inkwire_connections_by_kind", count, "transport=\"" + kind.first + "\",state=\"" + (kind.second ? "in-session" : "connected") + "\"");
  const ProcessFigures process = process_figures();
  m.one("process_resident_memory_bytes", "gauge", "Resident memory of the server process.", process.resident_bytes);
  m.one("process_open_fds", "gauge", "Open file descriptors of the server process (sockets, files).", process.descriptors);
  m.one("inkwire_process_threads", "gauge", "Threads of the server process.", process.threads);
  m.one("inkwire_sessions", "gauge", "Sessions this instance serves.", server.sessions().size());
  m.metric("inkwire_session_members", "gauge", "Members of each session on this instance.");
  for (const auto& [name, session] : server.sessions()) m.sample("inkwire_session_members", session->members(), "session=\"" + metric_label(name) + "\"");
  m.one("inkwire_messages_in_total", "counter", "Messages received from clients.", c.messages_in);
  m.one("inkwire_messages_out_total", "counter", "Messages written to clients.", c.messages_out);
  m.one("inkwire_queue_replaced_total", "counter", "State messages overtaken by a newer one in a client's queue (latest wins).", c.replaced);
  m.one("inkwire_queue_overflow_total", "counter", "Clients closed because they did not read their queue.", c.too_slow);
  m.one("inkwire_deadline_closed_total", "counter", "Clients closed past their deadline: nothing heard, or no write taken, for idle_timeout_seconds.", c.idle_closed);
  m.one("inkwire_connections_refused_total", "counter", "Connections refused past a connection cap.", server.admission().connections_refused());
  m.one("inkwire_joins_refused_total", "counter", "Joins refused for a wrong token.", server.admission().joins_refused());
  m.one("inkwire_changes_refused_total", "counter", "Changes refused: the member had no authority to make them.", c.changes_refused);
  m.metric("inkwire_call_dropped_total", "counter", "Call messages dropped (too frequent, too large, not JPEG, not Opus, video that does not decode), by reason.");
  for (const auto& [reason, count] : c.call.drops) m.sample("inkwire_call_dropped_total", count, "reason=\"" + metric_label(reason) + "\"");
  m.one("inkwire_call_crops_analysed_total", "counter", "Call members' face pictures analysed (JPEG crops and face-video frames).", c.call.crops);
  m.one("inkwire_call_analysis_seconds_total", "counter", "Time the call analyst spent on face crops.", c.call.seconds);
  m.one("inkwire_call_voice_relayed_total", "counter", "Voice packets relayed to call members (one per receiver).", c.call.voice_relayed);
  const SessionMaker& maker = server.maker();
  const MakingCounters& made = maker.counters();
  m.one("inkwire_rooms_open", "gauge", "Call rooms opened by their members (not configured) and not gone yet.", maker.open_rooms());
  m.one("inkwire_scenes_open", "gauge", "Scenes made from uploaded models and not gone yet.", maker.open_scenes());
  m.one("inkwire_rooms_opened_total", "counter", "Call rooms opened by their first member.", made.rooms_opened);
  m.one("inkwire_rooms_expired_total", "counter", "Call rooms gone after room_idle_seconds without members.", made.rooms_expired);
  m.one("inkwire_scenes_made_total", "counter", "Scenes made from uploaded models.", made.scenes_made);
  m.one("inkwire_scenes_expired_total", "counter", "Uploaded scenes gone after scene_idle_seconds without members.", made.scenes_expired);
  m.one("inkwire_models_replaced_total", "counter", "Models replaced in running scenes by their editors.", made.models_replaced);
  m.metric("inkwire_making_refused_total", "counter", "Rooms, scenes and uploads refused, by reason (policy, token, cap, cap-per-address, name, size, import, ...).");
  for (const auto& [reason, count] : made.refused) m.sample("inkwire_making_refused_total", count, "reason=\"" + metric_label(reason) + "\"");
  const RelayStatus r = server.relay().status();
  if (r.broker) {
    m.one("inkwire_broker_up", "gauge", "1 while the broker is reachable; 0 while this instance serves its own members only.", int(r.connected));
    m.one("inkwire_broker_published_total", "counter", "Changes handed to the broker.", r.published);
    m.one("inkwire_broker_received_total", "counter", "Changes the broker delivered (from every instance).", r.received);
    m.one("inkwire_broker_resyncs_total", "counter", "Session states read whole from the broker.", r.resyncs);
    m.one("inkwire_broker_reconnects_total", "counter", "Times the broker came back after it was lost.", r.reconnects);
    m.one("inkwire_broker_waiting_overflows_total", "counter", "Changes waiting for a resync that overflowed their bound (the state was read whole).", r.overflows);
    m.one("inkwire_broker_unsent", "gauge", "Changes made while the broker was away, waiting for it.", r.outbox);
    m.one("inkwire_broker_lag_seconds", "gauge", "From publishing this instance's latest change to its return from the broker.", r.lag_seconds);
  }
  return m.take();
}

}  // namespace inkwire::server
