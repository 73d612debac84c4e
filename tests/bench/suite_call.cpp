// inkwire-bench --suite call (SPEC F14): a call on loopback, measured as its people would feel
// it. One publisher (camera and microphone, through the client's own Publisher) and a listener
// (the client's CallAudio, as the window and recorder hear): downlink per listener per speaker
// (codes, voice, both) and uplink, against the same clip as WebRTC-style media (VP8 at 320x240
// 15 fps and Opus at 24 kbit/s, by ffmpeg); mouth-to-ear and capture-to-face latency; lip-sync
// (a face shown after its moment's sound); word accuracy of speech recognition (pocketsphinx)
// on what the listener heard against the original; server CPU per publisher and the publishers
// one analyst thread holds at 15 fps; then 6 publishers and 100 listeners in one session.
//
// The clip: a real face (a Yale development subject from ../shared/data when it is there, else
// libdlib's example photo) neutral, smiling, surprised, and a sentence spoken by espeak-ng.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "bench_harness.hpp"
#include "client/call/audio_file.hpp"
#include "client/call/call_audio.hpp"
#include "client/call/publisher.hpp"
#include "client/net/session_client.hpp"
#include "common/error.hpp"
#include "net_load.hpp"
#include "protocol/face_versions.hpp"
#include "server/server.hpp"

namespace inkwire::bench {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
const fs::path kYale = fs::path(INKWIRE_SHARED_DATA_DIR) / "yalefaces";
const fs::path kDlibPhoto = "/usr/share/doc/libdlib19.1/examples/faces/Tom_Cruise_avp_2014_4.jpg";
// Three Harvard sentences (IEEE 1969, list 1): 34 words, so one word is 3 points of accuracy.
const std::string kSentence =
    "the birch canoe slid on the smooth planks glue the sheet to the dark blue background "
    "it is easy to tell the depth of a well these days the chicken leg is a rare dish";

int run(const std::string& command) { return std::system(command.c_str()); }

// A folder of frames: a face neutral, smiling, surprised, neutral (`seconds` in all, played at
// 25 fps: a folder says no rate of its own).
fs::path face_clip(const fs::path& dir, const std::string& subject, double seconds) {
  const fs::path folder = dir / ("face-" + subject);
  fs::remove_all(folder);
  fs::create_directories(folder);
  const bool yale = fs::exists(kYale / "subject02_normal.png");
  const std::vector<std::string> labels = {"normal", "happy", "surprised", "normal"};
  const int frames = int(seconds * 25);
  for (int i = 0; i < frames; ++i) {
    const std::string label = labels[size_t(i * int(labels.size()) / frames)];
    const fs::path photo = yale ? kYale / ("subject" + subject + "_" + label + ".png") : kDlibPhoto;
    char name[32];
    std::snprintf(name, sizeof name, "%04d%s", i, photo.extension().c_str());
    fs::create_symlink(fs::absolute(photo), folder / name);
  }
  return folder;
}

// Words of `text`, lower case.
std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) {
    std::transform(w.begin(), w.end(), w.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    out.push_back(w);
  }
  return out;
}

// 1 - word error rate of `heard` against `said` (edit distance over words), at least 0.
double word_accuracy(const std::string& said, const std::string& heard) {
  const auto a = words_of(said), b = words_of(heard);
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
  return std::max(0.0, 1.0 - double(d[a.size()][b.size()]) / double(std::max<size_t>(a.size(), 1)));
}

// What pocketsphinx recognises in `wav` (any rate: resampled to 16 kHz first). Its general
// language model hears little in synthetic speech even before a call, so it listens for the
// sentence's own words in any order and number (a JSGF grammar): the same for the original and
// for what came through, so the two scores compare the sound, not the language model.
std::string recognised(const fs::path& wav, const fs::path& dir) {
  const fs::path at16 = dir / (wav.stem().string() + "-16k.wav");
  write_wav_mono(at16, read_wav_mono(wav, 16000), 16000);
  std::vector<std::string> words = words_of(kSentence);
  std::sort(words.begin(), words.end());
  words.erase(std::unique(words.begin(), words.end()), words.end());
  std::string alternatives;
  for (const std::string& w : words) alternatives += (alternatives.empty() ? "" : " | ") + w;
  const fs::path grammar = dir / "words.jsgf";
  std::ofstream(grammar) << "#JSGF V1.0;\ngrammar words;\npublic <s> = ( " << alternatives << " )* ;\n";
  const fs::path text = dir / (wav.stem().string() + ".txt");
  if (run("pocketsphinx_continuous -infile '" + at16.string() + "' -jsgf '" + grammar.string() + "' -logfn /dev/null > '" + text.string() +
          "' 2>/dev/null") != 0)
    throw Error("pocketsphinx_continuous failed on " + at16.string() + " (packages pocketsphinx, pocketsphinx-en-us)");
  std::ifstream in(text);
  std::string all, line;
  while (std::getline(in, line)) all += line + " ";
  return all;
}

uint64_t framed_bytes(const protocol::Message& m) { return protocol::encoded_size(m); }

struct ServerThread {
  asio::io_context io{1};
  std::unique_ptr<server::Server> server;
  std::thread thread;
  double cpu_seconds = 0;
  explicit ServerThread(const fs::path& data) {
    server::ServerConfig config = server::ServerConfig::embedded_default();
    config.port = 0;
    config.data_dir = data;
    config.sessions = {server::SessionConfig{.name = "call", .kind = protocol::SessionKind::Conference}};
    config.max_connections_per_address = 1000;
    server = std::make_unique<server::Server>(io, config);
    server->start();
    thread = std::thread([this] {
      io.run();
      cpu_seconds = thread_cpu_seconds();
    });
  }
  std::string address() const { return "127.0.0.1:" + std::to_string(server->port()); }
  void stop() {
    asio::post(io, [this] { server->stop(); });
    thread.join();
  }
};

}  // namespace

std::vector<Result> run_call_suite(Harness& harness) {
  if (std::system("command -v espeak-ng > /dev/null && command -v pocketsphinx_continuous > /dev/null") != 0)
    throw Error("the call suite needs espeak-ng, pocketsphinx and pocketsphinx-en-us (scripts/packages.txt)");
  const fs::path dir = fs::path(harness.options().output_dir.empty() ? "." : harness.options().output_dir) / "call-bench";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path speech = dir / "speech.wav";
  if (run("espeak-ng -s 140 -w '" + speech.string() + "' '" + kSentence + "'") != 0) throw Error("espeak-ng failed");
  const double speech_seconds = double(read_wav_mono(speech).size()) / kCallRate;
  const double clip_seconds = speech_seconds + 2.0;
  const fs::path clip = face_clip(dir, "02", clip_seconds);
  std::vector<Result> results;

  // --- One publisher, one listener.
  ServerThread server(dir / "data");
  SessionClient listener(server.address(), "listener");
  listener.join("call", "");
  const auto start = Clock::now();
  CallAudio audio(start);
  std::vector<float> heard;
  std::vector<double> mouth_to_ear, face_latency, lipsync;
  uint64_t voice_bytes = 0, code_bytes = 0;
  {
    SessionClient speaker(server.address(), "speaker");
    speaker.join("call", "");
    const PublisherOptions options{.camera = clip.string(), .microphone = speech.string()};
    Publisher publisher(speaker, options);
    const Clock::time_point publisher_start = publisher.clock_start();
    const auto end = Clock::now() + std::chrono::milliseconds(int64_t(clip_seconds * 1000));
    // Faces waiting for their moment's sound, as the clients show them (session_sync.cpp).
    std::vector<std::pair<Clock::time_point, Clock::time_point>> faces;  // (arrived, due)
    while (Clock::now() < end) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      const auto now = Clock::now();
      for (const auto& v : listener.take_voice()) {
        voice_bytes += framed_bytes(v.frame);
        audio.add(v.frame, v.arrived);
        // Heard when its first sample plays; spoken when a live microphone would have finished
        // the frame (the file's frames are sent as they start).
        if (const auto ear = audio.local_time(v.frame.member, v.frame.time_ms))
          mouth_to_ear.push_back(std::chrono::duration<double, std::milli>(*ear - (publisher_start + std::chrono::milliseconds(v.frame.time_ms))).count() + options.voice_frame_ms);
      }
      for (const auto& f : listener.take_member_faces()) {
        code_bytes += framed_bytes(f);
        if (f.source != protocol::FaceSource::Camera) continue;
        face_latency.push_back(std::chrono::duration<double, std::milli>(now - (publisher_start + std::chrono::milliseconds(f.time_ms))).count());
        if (const auto due = audio.local_time(f.member, f.time_ms)) lipsync.push_back(std::max(0.0, std::chrono::duration<double, std::milli>(now - *due).count()));
      }
      const auto sound = audio.take(now);
      heard.insert(heard.end(), sound.begin(), sound.end());
    }
    const uint64_t uplink = publisher.bytes_sent();
    const double seconds = std::chrono::duration<double>(Clock::now() - publisher.clock_start()).count();
    const uint64_t crops = publisher.crops_sent();
    server.stop();  // its I/O thread's CPU time is read as it ends
    const double analysis = server.server->counters().call.seconds;
    write_wav_mono(dir / "heard.wav", heard);
    const double accuracy = word_accuracy(kSentence, recognised(dir / "heard.wav", dir));
    const double accuracy_original = word_accuracy(kSentence, recognised(speech, dir));
    // The same clip as WebRTC-style media: VP8 at 320x240, 15 fps, and Opus at 24 kbit/s.
    const fs::path webm = dir / "webrtc-ref.webm";
    const std::string frames = (clip / "%04d").string() + fs::directory_iterator(clip)->path().extension().string();
    if (run("ffmpeg -v error -y -framerate 15 -i '" + frames + "' -i '" + speech.string() +
            "' -vf 'scale=320:240:force_original_aspect_ratio=decrease,pad=320:240:(ow-iw)/2:(oh-ih)/2,format=yuv420p' -c:v libvpx -deadline realtime -cpu-used 8 "
            "-b:v 250k -c:a libopus -b:a 24k -t " + std::to_string(clip_seconds) + " '" + webm.string() + "'") != 0)
      throw Error("ffmpeg could not make the WebRTC-style reference");
    const double webrtc_bps = double(fs::file_size(webm)) * 8 / clip_seconds;
    const double codes_bps = double(code_bytes) * 8 / seconds, voice_bps = double(voice_bytes) * 8 / seconds;
    const auto row = [&](const std::string& variant, std::map<std::string, double> counters) {
      Result r{.suite = "call", .renderer = "call", .variant = variant, .object = fs::exists(kYale) ? "yale02" : "dlib"};
      r.counters = std::move(counters);
      results.push_back(r);
    };
    const double downlink = codes_bps + voice_bps;
    // One analyst thread: the publishers it holds when each sends 15 crops a second.
    const double analyst_load_at_15 = crops > 0 ? analysis / seconds * 15.0 / (double(crops) / seconds) : 0;
    row("codes", {{"codes_bps", codes_bps}, {"downlink_bps", codes_bps}});
    row("voice", {{"voice_bps", voice_bps}, {"downlink_bps", voice_bps}});
    row("codes+voice", {{"codes_bps", codes_bps}, {"voice_bps", voice_bps}, {"downlink_bps", downlink},
                        {"uplink_bps", double(uplink) * 8 / seconds},
                        {"mouth_to_ear_ms_p50", percentile(mouth_to_ear, 0.5)}, {"mouth_to_ear_ms_p99", percentile(mouth_to_ear, 0.99)},
                        {"face_latency_ms_p99", percentile(face_latency, 0.99)},
                        {"lipsync_ms_mean", lipsync.empty() ? 0 : std::accumulate(lipsync.begin(), lipsync.end(), 0.0) / double(lipsync.size())},
                        {"lipsync_ms_max", lipsync.empty() ? 0 : *std::max_element(lipsync.begin(), lipsync.end())},
                        {"word_accuracy", accuracy}, {"word_accuracy_original", accuracy_original},
                        {"server_cpu_per_publisher", (analysis + server.cpu_seconds) / seconds},
                        {"max_publishers", analyst_load_at_15 > 0 ? std::floor(1.0 / analyst_load_at_15) : 0},
                        {"crops_per_second", double(crops) / seconds}, {"late_voice", double(audio.late())},
                        {"webrtc_over_downlink", webrtc_bps / std::max(downlink, 1.0)}});
    row("webrtc-ref", {{"downlink_bps", webrtc_bps}});
  }

  // --- The uplink (SPEC F17): each development subject (01-08), then each held-out one, neutral, smiling, surprised and
  // neutral again for two seconds each, speaking throughout, sent as JPEG crops and as VP8 video
  // to a listener: the publisher's bytes on the wire, how often the face the listener shows has
  // the expression of the picture (every 100 ms, past the first 700 ms of each expression), and
  // capture-to-face p99.
  // With the Yale faces, the held-out subjects (09-15, never looked at while tuning) too.
  const bool yale = fs::exists(kYale / "subject01_normal.png");
  std::vector<std::pair<std::string, std::vector<std::string>>> subject_sets = {{"dlib", {"02"}}};
  if (yale) subject_sets = {{"yale01-08", {"01", "02", "03", "04", "05", "06", "07", "08"}}, {"yale09-15", {"09", "10", "11", "12", "13", "14", "15"}}};
  for (const auto& [set_name, subjects] : subject_sets)
  for (const auto crops : {PublisherOptions::Crops::Jpeg, PublisherOptions::Crops::Vp8}) {
    std::vector<double> uplink_bps, latency;
    uint64_t samples = 0, matched = 0, analysed = 0;
    double analysis_seconds = 0;
    std::map<std::string, double> per_subject;
    for (const std::string& subject : subjects) {
      const fs::path folder = face_clip(dir / "uplink", subject, 8.0);
      ServerThread up(dir / ("data-uplink-" + subject));
      SessionClient viewer(up.address(), "viewer");
      viewer.join("call", "");
      SessionClient member(up.address(), "member");
      member.join("call", "");
      std::vector<protocol::MemberLayers> faces;
      Clock::time_point publisher_start;
      uint64_t sent_before = 0;
      double seconds = 0;
      {
        Publisher publisher(member, PublisherOptions{.camera = folder.string(), .microphone = speech.string(), .crops = crops});
        publisher_start = publisher.clock_start();
        sent_before = member.bytes_sent();  // the neutral photo, once, is not the stream's
        const auto end = publisher_start + std::chrono::milliseconds(8000);
        while (Clock::now() < end) {
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
          const auto now = Clock::now();
          for (const auto& f : viewer.take_member_faces()) {
            if (f.source != protocol::FaceSource::Camera) continue;
            faces.push_back(f);
            latency.push_back(std::chrono::duration<double, std::milli>(now - (publisher_start + std::chrono::milliseconds(f.time_ms))).count());
          }
        }
        seconds = std::chrono::duration<double>(Clock::now() - publisher_start).count();
        uplink_bps.push_back(double(member.bytes_sent() - sent_before) * 8 / seconds);
      }
      up.stop();
      analysed += up.server->counters().call.crops;
      analysis_seconds += up.server->counters().call.seconds;
      // The face shown at t: the newest received whose picture is not later than t.
      const std::vector<std::vector<Expression>> wanted = {{Expression::Neutral}, {Expression::Smile, Expression::Laugh}, {Expression::Surprise},
                                                           {Expression::Neutral}};
      uint64_t subject_samples = 0, subject_matched = 0;
      std::string shown_names;
      for (int t = 0; t < 8000; t += 100) {
        if (t % 2000 < 700) continue;
        std::optional<Expression> shown;
        for (const auto& f : faces)
          if (f.time_ms <= uint32_t(t)) shown = expression_from_code(protocol::member_face_of(f).expression.code);
        const auto& want = wanted[size_t(t / 2000)];
        ++subject_samples;
        subject_matched += shown && std::find(want.begin(), want.end(), *shown) != want.end();
        shown_names += std::string(t % 2000 == 700 ? " |" : " ") + (shown ? name_of(*shown) : "-");
      }
      samples += subject_samples;
      matched += subject_matched;
      per_subject["accuracy_subject" + subject] = double(subject_matched) / double(subject_samples);
      // What the listener showed, a word each 100 ms, the expressions apart by "|": which subject and
      // which expression lose.
      std::cerr << "uplink " << (crops == PublisherOptions::Crops::Vp8 ? "vp8" : "jpeg") << " subject" << subject << " shown:" << shown_names << "\n";
    }
    Result r{.suite = "call", .renderer = "call",
             .variant = std::string("uplink,crops=") + (crops == PublisherOptions::Crops::Vp8 ? "vp8" : "jpeg") + (set_name == "yale09-15" ? ",held-out" : ""),
             .object = set_name};
    r.counters = {{"uplink_bps", percentile(uplink_bps, 0.5)}, {"uplink_bps_max", *std::max_element(uplink_bps.begin(), uplink_bps.end())},
                  {"expression_accuracy", samples ? double(matched) / double(samples) : 0}, {"face_latency_ms_p99", percentile(latency, 0.99)},
                  {"face_latency_ms_p50", percentile(latency, 0.5)}, {"analysis_ms_mean", analysed ? analysis_seconds * 1000 / double(analysed) : 0}};
    r.counters.insert(per_subject.begin(), per_subject.end());
    results.push_back(r);
  }

  // --- Six publishers and a hundred listeners in one session: every receiver's voice counted
  // against what the server relayed, and each packet's time from its publisher's send.
  {
    ServerThread load(dir / "data-load");
    std::vector<std::unique_ptr<SessionClient>> clients;
    for (int i = 0; i < 100; ++i) {
      clients.push_back(std::make_unique<SessionClient>(load.address(), "listener-" + std::to_string(i)));
      clients.back()->join("call", "");
    }
    std::vector<std::unique_ptr<Publisher>> publishers;
    std::map<uint16_t, Clock::time_point> starts;  // by member number, once the roster says
    for (int i = 0; i < 6; ++i) {
      clients.push_back(std::make_unique<SessionClient>(load.address(), "speaker-" + std::to_string(i)));
      clients.back()->join("call", "");
      publishers.push_back(std::make_unique<Publisher>(*clients.back(), PublisherOptions{.camera = clip.string(), .microphone = speech.string()}));
    }
    const auto end = Clock::now() + std::chrono::milliseconds(int64_t(speech_seconds * 1000));
    uint64_t received = 0;
    std::vector<double> transit;
    while (Clock::now() < end) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      // Each speaker's own member number, as its roster says.
      for (size_t i = 0; i < publishers.size(); ++i)
        if (const uint16_t me = clients[100 + i]->roster().you) starts[me] = publishers[i]->clock_start();
      for (auto& c : clients)
        for (const auto& v : c->take_voice()) {
          ++received;
          if (const auto it = starts.find(v.frame.member); it != starts.end())
            transit.push_back(std::chrono::duration<double, std::milli>(v.arrived - (it->second + std::chrono::milliseconds(v.frame.time_ms))).count());
        }
    }
    publishers.clear();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    for (auto& c : clients) received += c->take_voice().size();
    clients.clear();
    load.stop();
    const double relayed = double(load.server->counters().call.voice_relayed);
    Result r{.suite = "call", .renderer = "call", .variant = "publishers=6,listeners=100", .object = fs::exists(kYale) ? "yale02" : "dlib"};
    r.counters = {{"delivered_fraction", relayed > 0 ? double(received) / relayed : 0}, {"p99_ms", percentile(transit, 0.99)},
                  {"voice_relayed", relayed}, {"crops_analysed", double(load.server->counters().call.crops)}};
    results.push_back(r);
  }
  // The browsers: voice with a quiet page and one whose thread stalls 400 ms in every 2 s, per
  // engine this machine has (tests/web/call_engines_test.py; Firefox and WebKit need a display,
  // which xvfb-run gives), and a person joining from Chromium, the time to the first face drawn
  // (tests/web/call_first_face.py).
  const std::string display = std::system("command -v xvfb-run > /dev/null") == 0 ? "xvfb-run -a -s '-screen 0 1024x768x24' " : "";
  for (const auto& [script_name, rows_name] : {std::pair{"call_engines_test.py", "browsers"}, std::pair{"call_first_face.py", "join"}}) {
    const fs::path script = fs::path(INKWIRE_SOURCE_DIR) / "tests/web" / script_name, json = dir / (std::string(rows_name) + ".json");
    run(display + "/usr/bin/python3 '" + script.string() + "' '" + INKWIRE_BIN_DIR + "' '" + (dir / rows_name).string() + "' --bench '" + json.string() + "'");
    // Parsed into a name of its own: a range-for over a member of a temporary would dangle.
    const nlohmann::json measured = fs::exists(json) ? nlohmann::json::parse(std::ifstream(json)) : nlohmann::json();
    if (measured.is_null()) std::fprintf(stderr, "inkwire-bench: the browsers' rows of %s did not run: none written\n", script_name);
    else
      for (const auto& row : measured.at("rows")) {
        Result b{.suite = "call", .renderer = "call", .variant = row.at("variant"), .object = "browser"};
        for (const auto& [key, value] : row.at("counters").items()) b.counters[key] = value.get<double>();
        results.push_back(std::move(b));
      }
  }
  return results;
}

}  // namespace inkwire::bench
