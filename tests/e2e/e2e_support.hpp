#pragma once
// What end-to-end tests share: a real inkwire-server on a free port with a given config,
// headless inkwire-client processes and their frame logs, image comparison.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <asio.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <opus.h>

#include "common/image.hpp"
#include "process.hpp"
#include "protocol/messages.hpp"

namespace inkwire::e2e {

namespace fs = std::filesystem;

// Faces the call tests publish: the Yale development subjects from ../shared/data when they are
// there (tests say so and check less without them), libdlib-dev's example photo, dlib's model.
inline const fs::path kYale = fs::path(INKWIRE_SOURCE_DIR) / ".." / "shared" / "data" / "yalefaces";
inline const fs::path kDlibPhoto = "/usr/share/doc/libdlib19.1/examples/faces/Tom_Cruise_avp_2014_4.jpg";
inline const fs::path kFaceModel = "/usr/share/dlib/shape_predictor_68_face_landmarks.dat";

inline fs::path output_dir(const std::string& test) {
  const fs::path dir = fs::path(INKWIRE_TEST_OUTPUT_DIR) / "e2e" / test;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The JSON log lines of `text` (a process's output) whose "event" is `event`.
inline std::vector<nlohmann::json> log_events(const std::string& text, const std::string& event) {
  std::vector<nlohmann::json> found;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_object() && j.value("event", "") == event) found.push_back(j);
  }
  return found;
}

// A server on a free port with `config` (the JSON of --config) and its data in DIR/data.
class ServerUnderTest {
 public:
  ServerUnderTest(const fs::path& dir, const nlohmann::json& config) : dir_(dir) {
    std::ofstream(dir / "server.json") << config.dump(2);
    start();
  }
  // (Re)starts the server on the same config and data.
  void start() {
    process_ = std::make_unique<Process>("inkwire-server", std::vector<std::string>{"--listen", "127.0.0.1:0", "--data", (dir_ / "data").string(), "--config", (dir_ / "server.json").string()},
                                         dir_ / ("server-" + std::to_string(starts_++) + ".log"));
    port_ = 0;
    eventually([&] {
      for (const auto& j : log_events(process_->output(), "listening")) port_ = j.value("port", 0);
      return port_ != 0 || !process_->running();
    });
    ASSERT_NE(port_, 0) << process_->output();
  }
  void kill() {
    process_->kill(SIGKILL);
    process_->wait();
  }
  std::string address() const { return "127.0.0.1:" + std::to_string(port_); }
  asio::ip::tcp::endpoint endpoint() const { return {asio::ip::make_address("127.0.0.1"), uint16_t(port_)}; }
  Process& process() { return *process_; }

 private:
  fs::path dir_;
  std::unique_ptr<Process> process_;
  int port_ = 0, starts_ = 0;
};

inline int http_port(ServerUnderTest& server) {
  int port = 0;
  eventually([&] {
    for (const auto& j : log_events(server.process().output(), "http-listening")) port = j.value("port", 0);
    return port != 0;
  });
  return port;
}

// A plain HTTP exchange: the whole answer, up to the server closing.
inline std::string http_get(int port, const std::string& request) {
  asio::io_context io;
  asio::ip::tcp::socket s(io);
  s.connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)});
  asio::write(s, asio::buffer(request));
  std::string answer;
  std::error_code ec;
  asio::read(s, asio::dynamic_buffer(answer), ec);
  return answer;
}

// What the server's /metrics says now (its config must give "http").
inline std::string metrics_of(ServerUnderTest& server) { return http_get(http_port(server), "GET /metrics HTTP/1.1\r\nHost: x\r\n\r\n"); }

// A headless client of `session` writing DIR/NAME-%04d.png and the frame log DIR/NAME.jsonl.
inline std::unique_ptr<Process> headless_client(const ServerUnderTest& server, const std::string& session, const fs::path& dir,
                                                const std::string& name, int frames, int fps) {
  return std::make_unique<Process>(
      "inkwire-client",
      std::vector<std::string>{"--connect", server.address(), "--session", session, "--headless", "--frames", std::to_string(frames),
                               "--fps", std::to_string(fps), "--size", "240x180", "--cache", (dir / ("cache-" + name)).string(),
                               "--out", (dir / (name + "-%04d.png")).string(), "--frame-log", (dir / (name + ".jsonl")).string(),
                               "--name", name},
      dir / (name + ".log"));
}

// Calls: `count` 20 ms Opus packets (12 kbit/s) of a voiced buzz, as a member's microphone sends them
// (`gain` 1: about -13 dBFS).
inline std::vector<protocol::Bytes> voice_packets(int count, float gain = 1.0f) {
  int error = 0;
  OpusEncoder* encoder = opus_encoder_create(48000, 1, OPUS_APPLICATION_VOIP, &error);
  opus_encoder_ctl(encoder, OPUS_SET_BITRATE(12000));
  std::vector<protocol::Bytes> packets;
  std::vector<float> pcm(960);
  for (int k = 0; k < count; ++k) {
    for (int i = 0; i < 960; ++i) {
      const float t = float(k * 960 + i) / 48000.0f;
      pcm[size_t(i)] = gain * (0.3f * std::sin(2 * 3.14159265f * 180 * t) + 0.15f * std::sin(2 * 3.14159265f * 720 * t));
    }
    protocol::Bytes out(400);
    out.resize(size_t(opus_encode_float(encoder, pcm.data(), 960, out.data(), opus_int32(out.size()))));
    packets.push_back(std::move(out));
  }
  opus_encoder_destroy(encoder);
  return packets;
}

// A call member of a roster by name, or null.
inline const protocol::CallMember* named(const protocol::Roster& roster, const std::string& name) {
  for (const auto& m : roster.members)
    if (m.name == name) return &m;
  return nullptr;
}

inline fs::path client_frame(const fs::path& dir, const std::string& name, int frame) {
  return dir / (name + "-" + std::to_string(10000 + frame).substr(1) + ".png");
}

inline std::vector<nlohmann::json> frame_log(const fs::path& file) {
  std::vector<nlohmann::json> lines;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (auto j = nlohmann::json::parse(line, nullptr, false); j.is_object()) lines.push_back(j);
  return lines;
}

inline int64_t monotonic_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Mean absolute difference per channel (0..255); 255 when the sizes differ.
inline double mean_difference(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return 255.0;
  double sum = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(int(a.pixels[i]) - int(b.pixels[i]));
  return sum / double(a.pixels.size());
}

}  // namespace inkwire::e2e
