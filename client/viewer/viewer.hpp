#pragma once
// The two faces of inkwire-client (SPEC N5): a headless recorder that renders N frames of a
// session to PNG or MP4, and an interactive window (mouse orbit, keys to switch styles, a live
// parameter panel) whose changes go to the whole session.
#include <string>

#include <glm/vec2.hpp>

#include "client/net/asset_cache.hpp"
#include "client/net/session_client.hpp"

namespace inkwire {

class Publisher;

struct ViewerOptions {
  glm::ivec2 size{640, 480};
  int frames = 0;            // headless: frames to render
  int fps = 24;              // frames per second, paced in real time so changes show as they come
  std::string out;           // headless: PNG, %04d pattern or .mp4
  std::string frame_log;     // optional JSON lines: one per frame drawn, with the revision it shows
  std::string gl = "osmesa"; // headless GL backend
  int msaa = 4;              // multisamples per pixel: antialiased edges (1 = off)
  // Turntable sessions: the visitor's own first view (azimuth, elevation in degrees, zoom: 1 the
  // photos' own scale); headless, the view then turns a full circle over the frames. Nothing of
  // it is sent.
  float azimuth = 0.0f, elevation = 0.0f, zoom = 1.0f;
  bool wait_for_product = false;  // headless: the first frame waits for every photo and cell, and the zoom level it needs
  // Presenter mode, off by default: this client's view of a product goes to the session as
  // object poses (present), or this client shows the view a presenter sends (follow).
  bool present = false, follow = false;
  // Calls: headless, the sound heard is written here (WAV) and, with an .mp4 --out, muxed into it.
  std::string audio_out;
  Publisher* publisher = nullptr;  // what this member publishes of itself (window keys mute and camera off)
};

int run_headless(SessionClient& client, AssetCache& cache, const ViewerOptions& options);
int run_window(SessionClient& client, AssetCache& cache, const ViewerOptions& options);

}  // namespace inkwire
