// libFuzzer target: what an instance reads back from the broker (docs/deploy.md): a published
// change (first byte 1 mod 3), a session's definition (0 mod 3) or a call's share (2 mod 3). Must
// end in a value that writes back to the same text's meaning, or protocol::ProtocolError; never
// a crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "protocol/framing.hpp"
#include "server/relay/broker_formats.hpp"

using namespace inkwire;

namespace {

std::string text_of(const protocol::Bytes& frame) { return std::string(frame.begin(), frame.end()); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    if (data[0] % 3 == 2) {
      const server::CallShare s = server::parse_call_share(text);
      const server::CallShare back = server::parse_call_share(server::call_share(s));
      if (back.origin != s.origin || back.session != s.session || back.message != s.message || back.photo_member != s.photo_member ||
          back.photo != s.photo || back.landmarks != s.landmarks || back.removal != s.removal)
        __builtin_trap();
    } else if (data[0] % 3 == 1) {
      const server::BrokerEvent e = server::parse_event(text);
      const std::string again = std::to_string(e.revision) + " " + server::event_header(e.published_us, e.sender, e.origin, e.session) +
                                text_of(protocol::encode(e.change));
      const server::BrokerEvent back = server::parse_event(again);
      if (back.revision != e.revision || back.sender != e.sender || back.origin != e.origin || back.session != e.session || back.change != e.change)
        __builtin_trap();
    } else {
      const server::StoredSession s = server::parse_session_definition(text);
      const server::StoredSession back = server::parse_session_definition(server::session_definition(s));
      if (back.token != s.token || back.editor_token != s.editor_token || !(back.state == s.state)) __builtin_trap();
    }
  } catch (const protocol::ProtocolError&) {
  }
  return 0;
}
