// Headless recording: one frame per tick of the clock, each drawn from the newest state.
#include <atomic>
#include <chrono>
#include <csignal>
#include <fstream>
#include <iostream>
#include <thread>

#include "client/gl/canvas.hpp"
#include "client/gl/context.hpp"
#include "client/output/frame_writer.hpp"
#include "client/viewer/frame_log.hpp"
#include "client/viewer/session_sync.hpp"
#include "client/viewer/viewer.hpp"
#include "client/call/audio_file.hpp"
#include "client/call/call_captions.hpp"
#include "common/error.hpp"

namespace inkwire {
namespace {

// Ctrl-C or a termination ends a recording early as if its last frame had come: what was
// recorded (pictures, sound, the frame log) is written whole.
std::atomic<bool> stop_asked{false};
void ask_to_stop(int) { stop_asked = true; }

// A call's sound: to --audio-out, and into an .mp4 recording beside its pictures (ffmpeg copies
// the video and adds the sound as AAC).
void save_call_sound(const ViewerOptions& o, const std::vector<float>& sound, const CallAudio& audio) {
  const bool mux = o.out.ends_with(".mp4");
  if (o.audio_out.empty() && !mux) return;
  const std::filesystem::path wav = o.audio_out.empty() ? std::filesystem::path(o.out + ".sound.wav") : std::filesystem::path(o.audio_out);
  write_wav_mono(wav, sound);
  std::cerr << "inkwire-client: " << audio.played() << " voice packets heard, " << audio.late() << " too late; sound in " << wav << "\n";
  if (mux) {
    const std::string muxed = o.out + ".muxed.mp4";
    const auto quoted = [](std::string s) {
      for (size_t at = 0; (at = s.find('\'', at)) != std::string::npos; at += 4) s.replace(at, 1, "'\\''");
      return "'" + s + "'";
    };
    const std::string command = "ffmpeg -loglevel error -y -i " + quoted(o.out) + " -i " + quoted(wav.string()) +
                                " -c:v copy -c:a aac -b:a 48k -shortest " + quoted(muxed);
    if (std::system(command.c_str()) != 0) throw Error("ffmpeg could not add the call's sound to " + o.out);
    std::filesystem::rename(muxed, o.out);
  }
  if (o.audio_out.empty()) std::filesystem::remove(wav);
}

}  // namespace

int run_headless(SessionClient& client, AssetCache& cache, const ViewerOptions& o) {
  if (o.frames <= 0) throw Error("--headless needs --frames N (1..100000)");
  if (o.out.empty()) throw Error("--headless needs --out PATH");
  std::signal(SIGINT, ask_to_stop);
  std::signal(SIGTERM, ask_to_stop);
  auto context = create_offscreen_context(o.size.x, o.size.y, o.gl);
  Canvas canvas(o.size.x, o.size.y, o.msaa);
  SessionSync sync(client, cache);
  FrameWriter writer(o.out, o.frames, o.fps, false);
  std::ofstream log;
  if (!o.frame_log.empty()) log.open(o.frame_log);
  const auto period = std::chrono::microseconds(1000000 / std::max(o.fps, 1));
  // A product's photos come one at a time (the tween data with the first of them): the first
  // frame waits for the photo nearest its view, or for all of them when asked to.
  sync.view().orbit().azimuth = o.azimuth;
  sync.view().orbit().elevation = o.elevation;
  sync.view().orbit().zoom = o.zoom;
  for (;;) {
    const bool changed = sync.poll();
    TurntableView* product = sync.view().turntable();
    if (product) product->set_display(o.size);
    if (!product || (!o.wait_for_product && product->samples_loaded() > 0)) break;
    if (product->complete() && !product->next_fetch(sync.view().orbit()) && !sync.fetching()) break;
    if (!client.connected()) throw Error("connection closed while the product was arriving");
    if (!changed) client.wait_for_update(client.updates(), std::chrono::milliseconds(sync.fetching() ? 2 : 50));
  }
  auto tick = std::chrono::steady_clock::now();
  // A call's sound, frame by frame on the same clock as the pictures.
  sync.audio().take(tick);
  std::vector<float> sound;
  bool call_seen = false;  // a call was shown at some frame: its sound is kept, even if all have left
  const auto hear_until = [&](std::chrono::steady_clock::time_point until) {
    const std::vector<float> heard = sync.audio().take(until);  // only what is due by now: late packets are late
    sound.insert(sound.end(), heard.begin(), heard.end());
  };
  int frames = 0;
  for (int i = 0; i < o.frames && !stop_asked; ++i, frames = i) {
    hear_until(tick);
    // The first frame shows what the wait above made ready (it has just polled): polling again
    // could take in the next photo first, and the first view would not be the one-photo view.
    if (i > 0) sync.poll();
    // A product's view is this visitor's own: a full turn over the frames, or, following, the
    // newest view a presenter sent; presenting, each frame's view goes to the session.
    TurntableOrbit& view = sync.view().orbit();
    if (o.follow) {
      view = TurntableOrbit::from_pose(sync.state().object);
    } else {
      view.azimuth = o.azimuth + 360.0f * float(i) / float(o.frames);
      view.elevation = o.elevation;
      view.zoom = o.zoom;
    }
    // A refused presenter stops: its views would only be refused again.
    if (o.present && sync.view().turntable() && client.refusals() == 0) client.send(view.pose(uint32_t(i + 1)));
    canvas.bind();
    sync.view().draw(o.size, double(i) / o.fps, i);
    Image picture = canvas.read();
    const bool in_call = !sync.view().call().empty();
    call_seen |= in_call;
    if (in_call) draw_call_captions(picture, sync.view().call().tiles());
    writer.write(picture);
    if (log) log << frame_log_line(sync, client, i).dump() << "\n" << std::flush;
    tick += period;
    std::this_thread::sleep_until(tick);
  }
  hear_until(tick);
  writer.close();
  if (call_seen || sync.audio().played() > 0) save_call_sound(o, sound, sync.audio());
  // Frames of a blank backdrop are not a recording of the session: say why and fail.
  if (!sync.view().content_error().empty()) throw Error(sync.view().content_error() + " (the frames written show none of it)");
  if (!sync.view().error().empty()) std::cerr << "inkwire-client: " << sync.view().error() << "\n";
  std::cerr << "inkwire-client: rendered " << frames << " frames to " << o.out << "; sent " << client.bytes_sent()
            << " bytes, received " << client.bytes_received() << "\n";
  return 0;
}

}  // namespace inkwire
