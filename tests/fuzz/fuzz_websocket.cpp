// libFuzzer target: the bytes a browser (or anyone) sends after the WebSocket upgrade, read by
// the server's own WebSocketTransport. The input is handed over as "read with the upgrade
// request"; once it is used up the socket (never connected) reports an error, so every frame
// the input holds is read, unmasked, checked and reassembled exactly as on a live connection.
#include <cstddef>
#include <cstdint>
#include <string>

#include <asio.hpp>

#include "protocol/framing.hpp"
#include "server/web/websocket.hpp"

namespace {

asio::awaitable<void> read_all(inkwire::server::WebSocketTransport& transport) {
  inkwire::protocol::Bytes frame;
  try {
    for (int i = 0; i < 1000; ++i) {
      if (co_await transport.read_frame(frame)) break;
      // A message that passed is exactly one protocol frame: it must decode or be refused.
      try {
        inkwire::protocol::decode_frame(frame.data(), frame.size());
      } catch (const inkwire::protocol::ProtocolError&) {
      }
    }
  } catch (const inkwire::protocol::ProtocolError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  asio::io_context io;
  inkwire::server::WebSocketTransport transport(inkwire::ByteStream(asio::ip::tcp::socket(io)), std::string(reinterpret_cast<const char*>(data), size));
  asio::co_spawn(io, read_all(transport), asio::detached);
  io.run();
  return 0;
}
