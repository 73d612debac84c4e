#pragma once
// The server's figures in Prometheus' text format (SPEC D2), for /metrics on the HTTP listener:
// connections, sessions and their members, messages in and out, what the send queues dropped or
// closed, refusals, and the broker's state and lag when instances share one.
#include <string>

namespace inkwire::server {

class Server;

std::string metrics_text(Server& server);
// Label values escaped as the format asks (backslash, double quote, line feed).
std::string metric_label(const std::string& value);

}  // namespace inkwire::server
