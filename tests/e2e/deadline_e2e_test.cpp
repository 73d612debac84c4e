// Deadlines for every connection (SPEC D7), end to end on 127.0.0.1 with short deadlines (idle 2 s,
// heartbeat 0.5 s): a call member that says hello, joins and then goes silent (a closed laptop lid:
// no FIN, no pongs) is closed and leaves the others' roster; one that keeps asking for data but
// never reads what it asked for is closed once a write waits that long; a quiet client that
// answers pings stays for three deadlines and more; a client whose server stops answering notices.
#include <thread>

#include <gtest/gtest.h>

#include "client/net/session_client.hpp"
#include "e2e_support.hpp"
#include "protocol/framing.hpp"

using namespace inkwire;
using namespace inkwire::e2e;

namespace {

constexpr double kIdle = 2.0, kBeat = 0.5;
const fs::path kMesh = fs::path(INKWIRE_MESH_DIR) / "cow.off";

nlohmann::json config(nlohmann::json extra = nlohmann::json::object()) {
  nlohmann::json c = {{"http", "127.0.0.1:0"}, {"idle_timeout_seconds", kIdle}, {"heartbeat_seconds", kBeat},
                      {"sessions", {{{"name", "call"}, {"kind", "conference"}}, {{"name", "cows"}, {"kind", "scene"}, {"assets", {{{"path", kMesh.string()}}}}}}}};
  c.update(extra);
  return c;
}

// A client written by hand: frames go out as the protocol says, and nothing is read unless asked.
class RawClient {
 public:
  explicit RawClient(const ServerUnderTest& server) : socket_(io_) { socket_.connect(server.endpoint()); }
  void send(const protocol::Message& m) { asio::write(socket_, asio::buffer(protocol::encode(m))); }
  void hello_and_join(const std::string& name, const std::string& session) {
    send(protocol::Hello{.client_name = name});
    send(protocol::Join{.session = session, .token = ""});
  }
  // Whether the server has closed this connection (reads and drops what is there meanwhile).
  bool closed_by_server() {
    std::array<uint8_t, 65536> buffer{};
    std::error_code ec;
    socket_.non_blocking(true);
    for (;;) {
      socket_.read_some(asio::buffer(buffer), ec);
      if (ec == asio::error::would_block) return false;
      if (ec) return true;
    }
  }
  asio::ip::tcp::socket& socket() { return socket_; }

 private:
  asio::io_context io_;
  asio::ip::tcp::socket socket_;
};

double metric(ServerUnderTest& server, const std::string& name) {
  const std::string text = metrics_of(server);
  const size_t at = text.find("\n" + name + " ");
  return at == std::string::npos ? -1 : std::stod(text.substr(at + name.size() + 2));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TEST(DeadlineE2ETest, AMemberThatGoesSilentIsClosedAndLeavesTheRosterWithinTheDeadline) {
  const fs::path dir = output_dir("deadline-silent");
  ServerUnderTest server(dir, config());
  SessionClient listener(server.address(), "Listener");
  listener.join("call", "");
  RawClient lid(server);
  lid.hello_and_join("Lid", "call");
  ASSERT_TRUE(eventually([&] { return named(listener.roster(), "Lid") != nullptr; })) << "the silent member never joined";
  // From here on it neither sends nor answers the server's pings.
  const auto start = std::chrono::steady_clock::now();
  ASSERT_TRUE(eventually([&] { return named(listener.roster(), "Lid") == nullptr; }, std::chrono::seconds(10)))
      << "a silent member stays in the roster";
  const double gone = seconds_since(start);
  EXPECT_GE(gone, kIdle * 0.9) << "closed before its deadline";
  EXPECT_LE(gone, kIdle + 1.5) << "closed long after its deadline";
  EXPECT_TRUE(eventually([&] { return lid.closed_by_server(); })) << "its socket is still open";
  EXPECT_EQ(log_events(server.process().output(), "idle-timeout").size(), 1u);
  EXPECT_GE(metric(server, "inkwire_deadline_closed_total"), 1);
  // What an operator watching for a slow leak reads there too.
  EXPECT_GT(metric(server, "process_resident_memory_bytes"), 1e6);
  EXPECT_GT(metric(server, "process_open_fds"), 3);
  EXPECT_GE(metric(server, "inkwire_process_threads"), 2);
  EXPECT_NE(metrics_of(server).find("inkwire_connections_by_kind{transport=\"tcp\",state=\"in-session\"} 1"), std::string::npos) << metrics_of(server);
  EXPECT_TRUE(listener.connected()) << "the listener, quiet but answering pings, was closed too: " << listener.last_error();
}

TEST(DeadlineE2ETest, AClientThatAsksButNeverReadsIsClosedOnceAWriteWaitsTheDeadline) {
  if (!fs::exists(kMesh)) GTEST_SKIP() << "libcgal-demo's cow.off is not extracted (run scripts/setup.sh)";
  const fs::path dir = output_dir("deadline-not-reading");
  // A queue far larger than what it asks for, so only the write deadline can close it.
  ServerUnderTest server(dir, config({{"queue_bytes", 256 << 20}}));
  SessionClient reader(server.address(), "Reader");
  const protocol::Snapshot snapshot = reader.join("cows", "");
  ASSERT_FALSE(snapshot.assets.empty());
  const protocol::AssetAnnounce& mesh = snapshot.assets[0];
  RawClient hoarder(server);
  hoarder.socket().set_option(asio::socket_base::receive_buffer_size(4096));
  hoarder.hello_and_join("Hoarder", "cows");
  // It keeps asking (so it is never silent) and never reads.
  const auto start = std::chrono::steady_clock::now();
  bool closed = false;
  while (!closed && seconds_since(start) < 15) {
    std::error_code ec;
    const protocol::Bytes request = protocol::encode(protocol::AssetRequest{.hash = mesh.hash, .offset = 0, .length = uint32_t(std::min<uint64_t>(mesh.size, protocol::kMaxChunk))});
    for (int i = 0; i < 20 && !ec; ++i) asio::write(hoarder.socket(), asio::buffer(request), ec);
    closed = bool(ec) || !log_events(server.process().output(), "not-reading").empty();
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_TRUE(closed) << "a client that reads nothing was not closed in 15 s";
  EXPECT_LE(seconds_since(start), kIdle + 8) << "closed long after its write deadline";
  EXPECT_EQ(log_events(server.process().output(), "not-reading").size(), 1u) << server.process().output();
  EXPECT_TRUE(reader.connected()) << "the reading client was closed too";
}

TEST(DeadlineE2ETest, AQuietClientThatAnswersPingsStaysForThreeDeadlines) {
  const fs::path dir = output_dir("deadline-quiet");
  ServerUnderTest server(dir, config());
  SessionClient quiet(server.address(), "Quiet"), other(server.address(), "Other");
  quiet.join("call", "");
  other.join("call", "");
  std::this_thread::sleep_for(std::chrono::duration<double>(3.5 * kIdle));
  EXPECT_TRUE(quiet.connected()) << quiet.last_error();
  const protocol::Roster roster = other.roster();
  EXPECT_NE(named(roster, "Quiet"), nullptr) << "a quiet member that answers pings left the roster";
  EXPECT_TRUE(log_events(server.process().output(), "idle-timeout").empty()) << server.process().output();
}

// Regression: a member that talks (it steers a scene it is alone in) but is sent nothing was
// never pinged, since the server pinged only peers it had not heard from; the client, hearing
// nothing from the server for SessionClient::kServerSilence, took it as gone and dropped the
// connection every 15 s. Now it is pinged within a beat or two as well.
TEST(DeadlineE2ETest, AMemberThatTalksButIsSentNothingIsPingedAllTheSame) {
  if (!fs::exists(kMesh)) GTEST_SKIP() << "libcgal-demo's cow.off is not extracted (run scripts/setup.sh)";
  const fs::path dir = output_dir("deadline-talker");
  ServerUnderTest server(dir, config());
  RawClient talker(server);
  talker.hello_and_join("Talker", "cows");
  protocol::FrameDecoder decoder;
  talker.socket().non_blocking(true);
  std::array<uint8_t, 65536> buffer{};
  bool pinged = false;
  const auto start = std::chrono::steady_clock::now();
  for (uint32_t sequence = 1; !pinged && seconds_since(start) < 6 * kBeat + 5; ++sequence) {
    talker.send(protocol::CameraPose{.sequence = sequence, .position = {0, 0, 3}, .target = {0, 0, 0}, .up = {0, 1, 0}, .fov_y_degrees = 40});
    std::error_code ec;
    for (size_t n; (n = talker.socket().read_some(asio::buffer(buffer), ec)) > 0 && !ec;) decoder.feed(buffer.data(), n);
    while (const auto m = decoder.next()) pinged |= std::holds_alternative<protocol::Ping>(*m);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // a drag's pace
  }
  EXPECT_TRUE(pinged) << "a member that talks but hears nothing was never pinged in " << seconds_since(start) << " s";
}

TEST(DeadlineE2ETest, AClientNoticesAServerThatStoppedAnswering) {
  const fs::path dir = output_dir("deadline-dead-server");
  ServerUnderTest server(dir, config());
  SessionClient client(server.address(), "Client");
  client.join("call", "");
  // A server that stops (a frozen machine, a cut cable): its socket stays open, nothing comes.
  server.process().kill(SIGSTOP);
  const auto start = std::chrono::steady_clock::now();
  const bool noticed = eventually([&] { return !client.connected(); }, SessionClient::kServerSilence + std::chrono::seconds(5));
  server.process().kill(SIGCONT);
  ASSERT_TRUE(noticed) << "the client still thinks it is connected";
  EXPECT_GE(seconds_since(start), double(SessionClient::kServerSilence.count()) * 0.9);
  EXPECT_NE(client.last_error().find("no word from the server"), std::string::npos) << client.last_error();
}

// A member whose connection dropped without a word joins again before the server noticed (SPEC
// F19): its silent twin gives way and the member keeps its number (the same tile), one tile in
// all; two live members of the same name from one address (two tabs of "guest") both stay.
TEST(DeadlineE2ETest, AMemberJoiningAgainReplacesItsSilentTwinAndKeepsItsNumber) {
  const fs::path dir = output_dir("deadline-rejoin");
  ServerUnderTest server(dir, config({{"idle_timeout_seconds", 30}, {"heartbeat_seconds", 5}}));
  SessionClient listener(server.address(), "Listener");
  listener.join("call", "");
  RawClient dropped(server);
  dropped.hello_and_join("Ada", "call");
  ASSERT_TRUE(eventually([&] { return named(listener.roster(), "Ada") != nullptr; }));
  const uint16_t number = named(listener.roster(), "Ada")->member;
  SessionClient guest1(server.address(), "guest"), guest2(server.address(), "guest");
  guest1.join("call", "");
  guest2.join("call", "");
  // Past a heartbeat and its answer: the dropped connection has said nothing since it joined.
  std::this_thread::sleep_for(std::chrono::seconds(9));
  SessionClient back(server.address(), "Ada");
  back.join("call", "");
  ASSERT_TRUE(eventually([&] { return listener.roster().members.size() == 4; })) << listener.roster().members.size() << " members";
  const protocol::Roster roster = listener.roster();
  EXPECT_EQ(std::count_if(roster.members.begin(), roster.members.end(), [](const auto& m) { return m.name == "Ada"; }), 1) << "two Ada tiles";
  EXPECT_EQ(named(roster, "Ada")->member, number) << "Ada came back under another number (another tile)";
  EXPECT_EQ(std::count_if(roster.members.begin(), roster.members.end(), [](const auto& m) { return m.name == "guest"; }), 2)
      << "a live member of the same name gave way";
  EXPECT_TRUE(eventually([&] { return dropped.closed_by_server(); })) << "the silent twin's socket is still open";
}
