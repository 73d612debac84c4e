// The server's HTTP listener on 127.0.0.1 (SPEC W1): a WebSocket client speaks the same protocol
// as a TCP one (hello, join, snapshot, a change that reaches a TCP member); a page of a foreign
// origin is refused; a text message, an oversized fragmented message and a slow-loris request
// head each close only that connection while another client carries on; /healthz and /metrics
// answer. A call member on a WebSocket hears the call by its voice route (GET /voice/TICKET, a
// streamed response) while it is open, and on its socket again once it closes; a ticket used,
// unknown or from a foreign page is refused.
#include <cmath>
#include <thread>

#include <asio.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "client/call/voice_codec.hpp"
#include "client/net/session_client.hpp"
#include "e2e_support.hpp"
#include "protocol/framing.hpp"

using namespace inkwire;
using namespace inkwire::e2e;
using asio::ip::tcp;

namespace {

const fs::path kMesh = fs::path(INKWIRE_MESH_DIR) / "cow.off";

nlohmann::json web_config() {
  return {{"http", "127.0.0.1:0"}, {"http_head_timeout_seconds", 1.0},
          {"sessions", {{{"name", "cows"}, {"kind", "scene"}, {"assets", {{{"path", kMesh.string()}}}}}}}};
}

// A minimal WebSocket client: the upgrade, masked frames out, whole frames in.
class WebSocket {
 public:
  WebSocket(int port, const std::string& origin) : socket_(io_) {
    socket_.connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)});
    const std::string request = "GET /ws HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
                                "\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
                                "Sec-WebSocket-Version: 13\r\nOrigin: " + origin + "\r\n\r\n";
    asio::write(socket_, asio::buffer(request));
    std::error_code ec;
    const size_t n = asio::read_until(socket_, asio::dynamic_buffer(buffer_), "\r\n\r\n", ec);
    head_ = ec ? buffer_ : buffer_.substr(0, n);
    buffer_.erase(0, ec ? buffer_.size() : n);
  }
  const std::string& head() const { return head_; }
  bool upgraded() const { return head_.rfind("HTTP/1.1 101", 0) == 0; }

  void send_raw(uint8_t first_byte, const protocol::Bytes& payload) {
    protocol::Bytes frame = {first_byte};
    const uint8_t mask[4] = {0x12, 0x34, 0x56, 0x78};
    if (payload.size() < 126) {
      frame.push_back(uint8_t(0x80 | payload.size()));
    } else if (payload.size() <= 0xffff) {
      frame.insert(frame.end(), {0x80 | 126, uint8_t(payload.size() >> 8), uint8_t(payload.size())});
    } else {
      frame.push_back(0x80 | 127);
      for (int i = 7; i >= 0; --i) frame.push_back(uint8_t(uint64_t(payload.size()) >> (8 * i)));
    }
    frame.insert(frame.end(), mask, mask + 4);
    for (size_t i = 0; i < payload.size(); ++i) frame.push_back(payload[i] ^ mask[i % 4]);
    std::error_code ec;
    asio::write(socket_, asio::buffer(frame), ec);
  }
  void send(const protocol::Message& m) { send_raw(0x82, protocol::encode(m)); }

  // The status code of the server's Close frame (0: none came).
  int close_code() const { return close_code_; }
  // The next protocol message, or nothing when the server closed the connection.
  std::optional<protocol::Message> receive() {
    std::error_code ec;
    auto need = [&](size_t n) {
      while (buffer_.size() < n && !ec) {
        char chunk[4096];
        const size_t got = socket_.read_some(asio::buffer(chunk), ec);
        buffer_.append(chunk, got);
      }
      return buffer_.size() >= n;
    };
    if (!need(2)) return std::nullopt;
    size_t size = uint8_t(buffer_[1]) & 0x7f, at = 2;
    if (size == 126) {
      if (!need(4)) return std::nullopt;
      size = size_t(uint8_t(buffer_[2])) << 8 | uint8_t(buffer_[3]), at = 4;
    } else if (size == 127) {
      if (!need(10)) return std::nullopt;
      size = 0;
      for (int i = 0; i < 8; ++i) size = size << 8 | uint8_t(buffer_[size_t(2 + i)]);
      at = 10;
    }
    if (!need(at + size)) return std::nullopt;
    const uint8_t opcode = uint8_t(buffer_[0]) & 0x0f;
    const protocol::Bytes frame(buffer_.begin() + long(at), buffer_.begin() + long(at + size));
    buffer_.erase(0, at + size);
    if (opcode == 0x8) {  // Close: the server's last word, with the code that says why
      close_code_ = frame.size() >= 2 ? frame[0] << 8 | frame[1] : 0;
      return std::nullopt;
    }
    const auto header = protocol::parse_header(frame.data());
    return protocol::decode(header.type, frame.data() + protocol::kHeaderBytes, frame.size() - protocol::kHeaderBytes);
  }
  // Messages until the server closes: true when it did (within the server's one-second cut-off).
  bool closed_after_error(std::string* reason = nullptr) {
    for (int i = 0; i < 100; ++i) {
      const auto m = receive();
      if (!m) return true;
      if (const auto* e = std::get_if<protocol::ErrorMessage>(&*m); e && reason) *reason = e->reason;
    }
    return false;
  }

 private:
  asio::io_context io_;
  tcp::socket socket_;
  std::string buffer_, head_;
  int close_code_ = 0;
};

}  // namespace

class WebTransportE2ETest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kMesh)) GTEST_SKIP() << "libcgal-demo's cow.off is not extracted (run scripts/setup.sh)";
  }
};

TEST_F(WebTransportE2ETest, AWebSocketClientSpeaksTheProtocolWithTcpMembersOfTheSameSession) {
  const fs::path dir = output_dir("web-transport");
  ServerUnderTest server(dir, web_config());
  const int port = http_port(server);
  ASSERT_NE(port, 0) << server.process().output();
  const std::string own = "http://127.0.0.1:" + std::to_string(port);
  WebSocket ws(port, own);
  ASSERT_TRUE(ws.upgraded()) << ws.head();
  EXPECT_NE(ws.head().find("Sec-WebSocket-Accept: s3pPLMBiTxaQ9kYGzzhZRbK+xOo="), std::string::npos) << ws.head();  // RFC 6455's example
  ws.send(protocol::Hello{.client_name = "browser"});
  ASSERT_TRUE(std::holds_alternative<protocol::Welcome>(*ws.receive()));
  ws.send(protocol::Join{.session = "cows", .token = ""});
  const auto snapshot = ws.receive();
  ASSERT_TRUE(snapshot && std::holds_alternative<protocol::Snapshot>(*snapshot));
  EXPECT_EQ(std::get<protocol::Snapshot>(*snapshot).assets.size(), 1u);
  // Then what this member may not change: nothing, in a scene without an editor token.
  const auto permissions = ws.receive();
  ASSERT_TRUE(permissions && std::holds_alternative<protocol::Permissions>(*permissions));
  EXPECT_TRUE(std::get<protocol::Permissions>(*permissions).refused.empty());
  // A TCP member's change reaches the WebSocket member, and the other way round.
  SessionClient tcp(server.address(), "tcp");
  tcp.join("cows", "");
  tcp.send(protocol::StyleChange{.renderer = "comic", .settings = {}});
  const auto change = ws.receive();
  ASSERT_TRUE(change && std::holds_alternative<protocol::StyleChange>(*change));
  EXPECT_EQ(std::get<protocol::StyleChange>(*change).renderer, "comic");
  const uint64_t seen = tcp.updates();
  ws.send(protocol::StyleChange{.renderer = "hatching", .settings = {}});
  tcp.wait_for_update(seen, std::chrono::seconds(5));
  EXPECT_EQ(tcp.state().style.renderer, "hatching");

  const std::string health = http_get(port, "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n");
  EXPECT_EQ(health.rfind("HTTP/1.1 200", 0), 0u) << health;
  const std::string metrics = http_get(port, "GET /metrics HTTP/1.1\r\nHost: x\r\n\r\n");
  EXPECT_NE(metrics.find("inkwire_connections 2"), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("inkwire_session_members{session=\"cows\"} 2"), std::string::npos) << metrics;
  EXPECT_NE(http_get(port, "GET / HTTP/1.1\r\nHost: x\r\n\r\n").find("cows"), std::string::npos);
  EXPECT_EQ(http_get(port, "GET /nothing HTTP/1.1\r\nHost: x\r\n\r\n").rfind("HTTP/1.1 404", 0), 0u);
  EXPECT_EQ(http_get(port, "POST /ws HTTP/1.1\r\nHost: x\r\n\r\n").rfind("HTTP/1.1 405", 0), 0u);
  // A header given twice, a name that is no token, a control character: 400, not a guess.
  for (const char* head : {"GET / HTTP/1.1\r\nHost: x\r\nHost: y\r\n\r\n", "GET / HTTP/1.1\r\nHo st: x\r\n\r\n",
                           "GET / HTTP/1.1\r\nHost: x\x01y\r\n\r\n", "GET /ws HTTP/1.1\r\nUpgrade: websocket\r\nupgrade: h2c\r\n\r\n"}) {
    const std::string answer = http_get(port, head);
    EXPECT_EQ(answer.rfind("HTTP/1.1 400", 0), 0u) << head << " -> " << answer;
  }
}

TEST_F(WebTransportE2ETest, ForeignOriginsTextMessagesOversizedMessagesAndSlowHeadsAreCutOffWhileOthersCarryOn) {
  const fs::path dir = output_dir("web-refusals");
  nlohmann::json config = web_config();
  ServerUnderTest server(dir, config);
  const int port = http_port(server);
  ASSERT_NE(port, 0) << server.process().output();
  const std::string own = "http://127.0.0.1:" + std::to_string(port);
  // The bystander: a WebSocket member that must be served throughout.
  WebSocket bystander(port, own);
  ASSERT_TRUE(bystander.upgraded());
  bystander.send(protocol::Hello{.client_name = "bystander"});
  ASSERT_TRUE(bystander.receive());
  auto still_served = [&](uint64_t nonce) {
    bystander.send(protocol::Ping{.nonce = nonce});
    const auto pong = bystander.receive();
    return pong && std::holds_alternative<protocol::Pong>(*pong) && std::get<protocol::Pong>(*pong).nonce == nonce;
  };

  WebSocket foreign(port, "https://evil.example");
  EXPECT_EQ(foreign.head().rfind("HTTP/1.1 403", 0), 0u) << foreign.head();
  EXPECT_TRUE(still_served(1));

  WebSocket text(port, own);
  ASSERT_TRUE(text.upgraded());
  text.send_raw(0x81, protocol::Bytes{'h', 'i'});
  std::string reason;
  EXPECT_TRUE(text.closed_after_error(&reason));
  EXPECT_NE(reason.find("text WebSocket message"), std::string::npos) << reason;
  EXPECT_EQ(text.close_code(), 1002) << "a protocol error";
  EXPECT_TRUE(still_served(2));

  // Fragments that add up past one frame's limit: cut off before the rest is read.
  WebSocket big(port, own);
  ASSERT_TRUE(big.upgraded());
  big.send(protocol::Hello{.client_name = "big"});
  ASSERT_TRUE(big.receive());
  const protocol::Bytes fragment(100 * 1024, 0);
  big.send_raw(0x02, fragment);  // binary, not final
  big.send_raw(0x00, fragment);  // continuation past 128 KiB
  EXPECT_TRUE(big.closed_after_error(&reason));
  EXPECT_NE(reason.find("over the frame limit"), std::string::npos) << reason;
  EXPECT_EQ(big.close_code(), 1009) << "a message too big";
  EXPECT_TRUE(still_served(3));

  // Half a request head, then nothing: cut off after the head timeout (1 s here).
  asio::io_context io;
  tcp::socket slow(io);
  slow.connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)});
  asio::write(slow, asio::buffer(std::string("GET /healthz HTTP/1.1\r\nHost: x\r\n")));
  const auto start = std::chrono::steady_clock::now();
  char byte;
  std::error_code ec;
  slow.read_some(asio::buffer(&byte, 1), ec);
  EXPECT_TRUE(ec) << "the server answered a request it never finished";
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
  EXPECT_TRUE(still_served(4));
  EXPECT_FALSE(log_events(server.process().output(), "http-too-slow").empty());
}

namespace {

// The voice frames of a voice route's chunked body as they come, until `count` or the end.
std::vector<protocol::VoiceFrame> voice_from_route(tcp::socket& socket, std::string& pending, size_t count) {
  std::vector<protocol::VoiceFrame> frames;
  std::string body;
  std::error_code ec;
  while (frames.size() < count && !ec) {
    // Chunks: hex size CRLF, bytes, CRLF; their bytes are frames as on the wire.
    for (size_t line; (line = pending.find("\r\n")) != std::string::npos;) {
      const size_t size = std::stoul(pending.substr(0, line), nullptr, 16);
      if (pending.size() < line + 2 + size + 2) break;
      body += pending.substr(line + 2, size);
      pending.erase(0, line + 2 + size + 2);
    }
    protocol::FrameDecoder decoder;
    decoder.feed(reinterpret_cast<const uint8_t*>(body.data()), body.size());
    size_t used = 0;
    while (const auto m = decoder.next()) {
      used += protocol::encoded_size(*m);
      if (const auto* voice = std::get_if<protocol::VoiceFrame>(&*m)) frames.push_back(*voice);
    }
    body.erase(0, used);
    if (frames.size() >= count) break;
    char chunk[4096];
    const size_t got = socket.read_some(asio::buffer(chunk), ec);
    pending.append(chunk, got);
  }
  return frames;
}

}  // namespace

TEST_F(WebTransportE2ETest, ACallMemberOnAWebSocketHearsTheCallByItsVoiceRouteWhileOpenAndOnItsSocketAfter) {
  const fs::path dir = output_dir("web-voice-route");
  ServerUnderTest server(dir, {{"http", "127.0.0.1:0"}, {"sessions", {{{"name", "talk"}, {"kind", "conference"}}}}});
  const int port = http_port(server);
  ASSERT_NE(port, 0) << server.process().output();
  const std::string own = "http://127.0.0.1:" + std::to_string(port);
  WebSocket ws(port, own);
  ASSERT_TRUE(ws.upgraded()) << ws.head();
  ws.send(protocol::Hello{.client_name = "browser"});
  ws.send(protocol::Join{.session = "talk", .token = ""});
  std::string ticket;
  for (int i = 0; i < 20 && ticket.empty(); ++i) {
    const auto m = ws.receive();
    ASSERT_TRUE(m) << "closed before a voice route came";
    if (const auto* route = std::get_if<protocol::VoiceRoute>(&*m)) ticket = route->ticket;
  }
  ASSERT_EQ(ticket.size(), 32u);

  // A native member speaks a tone for the whole test, 60 ms packets.
  SessionClient speaker(server.address(), "speaker");
  speaker.join("talk", "");
  speaker.send(protocol::Publish{.camera = false, .microphone = true});
  std::atomic<bool> speaking = true;
  std::thread voice([&] {
    VoiceEncoder encoder(60, 10000);
    std::vector<float> samples(size_t(encoder.frame_samples()));
    for (uint32_t k = 0; speaking; ++k) {
      for (size_t i = 0; i < samples.size(); ++i) samples[i] = 0.3f * float(std::sin(2 * M_PI * 220.0 * double(k * samples.size() + i) / 48000.0));
      speaker.send(protocol::VoiceFrame{.member = 0, .time_ms = k * 60, .opus = encoder.encode(samples)});
      std::this_thread::sleep_for(std::chrono::milliseconds(60));
    }
  });
  struct Stop {
    std::atomic<bool>& speaking;
    std::thread& voice;
    ~Stop() { speaking = false, voice.join(); }
  } stop{speaking, voice};
  // Heard on the socket first.
  bool heard_on_socket = false;
  for (int i = 0; i < 200 && !heard_on_socket; ++i) heard_on_socket = std::holds_alternative<protocol::VoiceFrame>(*ws.receive());
  ASSERT_TRUE(heard_on_socket) << "the WebSocket member heard nothing before opening its route";

  // A foreign page, an unknown ticket and a malformed one are refused.
  EXPECT_EQ(http_get(port, "GET /voice/" + ticket + " HTTP/1.1\r\nHost: x\r\nOrigin: https://evil.example\r\n\r\n").rfind("HTTP/1.1 403", 0), 0u);
  EXPECT_EQ(http_get(port, "GET /voice/0123456789abcdef0123456789abcdef HTTP/1.1\r\nHost: x\r\n\r\n").rfind("HTTP/1.1 404", 0), 0u);
  EXPECT_EQ(http_get(port, "GET /voice/../ws HTTP/1.1\r\nHost: x\r\n\r\n").rfind("HTTP/1.1 404", 0), 0u);

  // The route: a chunked body of voice frames, and none of them on the socket meanwhile.
  asio::io_context io;
  tcp::socket route(io);
  route.connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)});
  asio::write(route, asio::buffer("GET /voice/" + ticket + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\nOrigin: " + own + "\r\n\r\n"));
  std::string pending;
  const size_t head_end = asio::read_until(route, asio::dynamic_buffer(pending), "\r\n\r\n");
  const std::string head = pending.substr(0, head_end);
  pending.erase(0, head_end);
  ASSERT_EQ(head.rfind("HTTP/1.1 200", 0), 0u) << head;
  EXPECT_NE(head.find("Transfer-Encoding: chunked"), std::string::npos) << head;
  EXPECT_NE(head.find("Cache-Control: no-store"), std::string::npos) << head;
  const std::vector<protocol::VoiceFrame> routed = voice_from_route(route, pending, 10);
  ASSERT_EQ(routed.size(), 10u) << "the route carried too little voice";
  const uint32_t first = routed.front().time_ms, last = routed.back().time_ms;
  EXPECT_EQ(last - first, 9u * 60) << "the route lost or reordered packets";
  // Used once: the same ticket again is refused.
  EXPECT_EQ(http_get(port, "GET /voice/" + ticket + " HTTP/1.1\r\nHost: x\r\n\r\n").rfind("HTTP/1.1 404", 0), 0u);
  route.close();

  // Closed: the voice comes on the socket again, and what the route carried never came there.
  bool after = false;
  for (int i = 0; i < 400 && !after; ++i) {
    const auto m = ws.receive();
    ASSERT_TRUE(m);
    if (const auto* v = std::get_if<protocol::VoiceFrame>(&*m)) {
      EXPECT_FALSE(v->time_ms >= first && v->time_ms <= last) << "packet " << v->time_ms << " came by both routes";
      after = v->time_ms > last;
    }
  }
  EXPECT_TRUE(after) << "voice did not come back to the socket once the route closed";
}
