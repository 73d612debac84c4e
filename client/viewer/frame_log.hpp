#pragma once
// One JSON line per frame a client draws (--frame-log): what it showed and when, for tests and
// benchmarks that follow a client from outside (which revision, style, product progress).
#include <nlohmann/json.hpp>

#include "client/net/session_client.hpp"
#include "client/viewer/session_sync.hpp"

namespace inkwire {

// frame, revision, style, monotonic_us (CLOCK_MONOTONIC: comparable across processes), and
// product or expression where the session has one.
nlohmann::json frame_log_line(SessionSync& sync, const SessionClient& client, long frame);

}  // namespace inkwire
