// inkwire-client: joins a session and draws it locally, in a window or headless (docs/cli.md).
#include <csignal>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>

#include "client/call/publisher.hpp"
#include "client/gl/context.hpp"
#include "client/viewer/session_view.hpp"
#include "client/viewer/viewer.hpp"
#include "protocol/net/byte_stream.hpp"
#include "common/error.hpp"

using namespace inkwire;

int main(int argc, char** argv) {
  std::string connect = "127.0.0.1:7878", session, token, size = "640x480", cache_dir, style, view, name = "inkwire-client", ca;
  std::vector<std::string> settings;
  bool headless = false;
  ViewerOptions o;
  CLI::App app{"inkwire-client: joins an Inkwire session and draws it locally (window, or headless to PNG/MP4)"};
  app.add_option("--connect", connect, "server HOST:PORT");
  app.add_option("--session", session, "session name")->required();
  app.add_option("--token", token, "the session's token, if it has one");
  bool tls = false;
  app.add_flag("--tls", tls, "connect over TLS (a server with \"tls\" in its config); its certificate must name the --connect host");
  app.add_option("--ca", ca, "with --tls: PEM file of the certificate authority (or the server's own certificate) to trust instead of the system's");
  app.add_flag("--headless", headless, "render to files instead of a window (the default without a display)");
  app.add_option("--frames", o.frames, "headless: frames to render")->check(CLI::Range(1, 100000));
  app.add_option("--fps", o.fps, "frames per second (paced in real time)")->check(CLI::Range(1, 240));
  app.add_option("--out", o.out, "headless: output PNG, %04d pattern or .mp4");
  app.add_option("--size", size, "window or image size WxH");
  app.add_option("--cache", cache_dir, "asset cache folder (default ~/.cache/inkwire)");
  app.add_option("--name", name, "this client's name in the server's logs");
  app.add_option("--style", style, "after joining, change the session's style to this (every client follows)");
  app.add_option("--set", settings, "KEY=VALUE setting for --style (repeatable)");
  app.add_option("--view", view,
                 "after joining, move the session's camera: AZIMUTH,ELEVATION[,DISTANCE in diagonals]; in a turntable session, "
                 "this client's own first view (AZIMUTH[,ELEVATION[,ZOOM]], nothing sent)");
  app.add_flag("--wait-for-product", o.wait_for_product, "headless, turntable sessions: draw the first frame once every photo is there, and the zoom level its view needs");
  app.add_flag("--present", o.present, "turntable sessions: send this client's view to the session for followers (window: P toggles)");
  app.add_flag("--follow", o.follow, "turntable sessions: show the view a presenter sends (window: F toggles)")->excludes("--present");
  app.add_option("--frame-log", o.frame_log, "write one JSON line per frame drawn (frame, revision, style, time; the window adds its panel's place)");
  app.add_option("--msaa", o.msaa, "samples per pixel for antialiased edges (1 = off)")->check(CLI::Range(1, 16));
  app.add_option("--gl", o.gl, "headless GL backend: osmesa, egl or auto");
  PublisherOptions call;
  app.add_option("--camera", call.camera, "calls: publish this member's face from camera:N, a video file or a folder of images");
  app.add_option("--microphone", call.microphone, "calls: publish this member's voice from 'default' (the sound input) or a WAV file");
  app.add_option("--photo", call.photo, "calls: this member's neutral photo (default: the camera's first picture)");
  app.add_option("--voice-bitrate", call.voice_bitrate, "calls: Opus bits a second (default 10000)")->check(CLI::Range(6000, 12000));
  app.add_option("--voice-frame-ms", call.voice_frame_ms, "calls: milliseconds of voice per packet: 20, 40 or 60 (default)")
      ->check(CLI::IsMember({20, 40, 60}));
  const std::map<std::string, PublisherOptions::Crops> crops{{"vp8", PublisherOptions::Crops::Vp8}, {"jpeg", PublisherOptions::Crops::Jpeg}};
  app.add_option("--crops", call.crops, "calls: send the face as vp8 video (default) or as separate jpeg crops (about 8 times the bits)")
      ->transform(CLI::CheckedTransformer(crops, CLI::ignore_case));
  bool open_room = false;
  app.add_flag("--new", open_room, "calls: open a call room of the --session name when no session has it (you are then its host); without it an "
                                   "unknown name is refused, so a typo makes no empty room");
  bool rejoin = true;
  app.add_flag("--rejoin,!--no-rejoin", rejoin, "join again under the same name when the connection drops, every 2 s for a minute (default: on)");
  app.add_option("--audio-out", o.audio_out, "calls, headless: write the sound heard to this WAV file (an .mp4 --out gets it too)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (std::sscanf(size.c_str(), "%dx%d", &o.size.x, &o.size.y) != 2 || o.size.x < 16 || o.size.y < 16 || o.size.x > 8192 || o.size.y > 8192)
      throw Error("--size '" + size + "' is not WxH with sides 16..8192");
    if (!settings.empty() && style.empty()) throw Error("--set needs --style");
    std::signal(SIGPIPE, SIG_IGN);
    AssetCache cache(cache_dir.empty() ? AssetCache::default_dir() : std::filesystem::path(cache_dir));
    if (!ca.empty() && !tls) throw Error("--ca needs --tls");
    SessionClient client(connect, name, tls ? client_tls_context(ca) : nullptr);
    client.set_rejoin(rejoin);
    const protocol::Snapshot joined = client.join(session, token, open_room);
    if (!style.empty()) client.send(protocol::StyleChange{.renderer = style, .settings = settings});
    if (!view.empty() && !joined.product.directions.empty()) {
      // A product's view is the visitor's own (SPEC T13).
      if (std::sscanf(view.c_str(), "%f,%f,%f", &o.azimuth, &o.elevation, &o.zoom) < 1 || std::abs(o.elevation) > 90.0f ||
          !(o.zoom >= 0.5f && o.zoom <= 4.0f))
        throw Error("--view '" + view + "' is not AZIMUTH[,ELEVATION[,ZOOM]] with elevation -90..90 and zoom 0.5..4");
    } else if (!view.empty()) {
      float az = 0, el = 0, dist = 1.4f;
      if (std::sscanf(view.c_str(), "%f,%f,%f", &az, &el, &dist) < 2 || dist <= 0.05f || dist > 1000.0f)
        throw Error("--view '" + view + "' is not AZIMUTH,ELEVATION[,DISTANCE]");
      client.send(orbit_pose(az, el, dist, 1));
    }
    if (!headless && !window_system_available()) {
      if (o.frames == 0 || o.out.empty()) throw Error("no display: run with --headless --frames N --out PATH");
      headless = true;
    }
    // A call member publishes its own face and voice (SPEC F7); without sources it listens.
    std::unique_ptr<Publisher> publisher;
    if (!call.camera.empty() || !call.microphone.empty() || !call.photo.empty()) {
      if (joined.kind != protocol::SessionKind::Conference) throw Error("--camera, --microphone and --photo are for calls (conference sessions)");
      publisher = std::make_unique<Publisher>(client, call);
      o.publisher = publisher.get();
    }
    return headless ? run_headless(client, cache, o) : run_window(client, cache, o);
  } catch (const std::exception& e) {
    std::cerr << "inkwire-client: " << e.what() << "\n";
    return 1;
  }
}
