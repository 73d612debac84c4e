// inkwire-render: one mesh, one style, to images or video (docs/cli.md).
#include <algorithm>
#include <cstdio>
#include <optional>
#include <iostream>
#include <numbers>

#include <CLI/CLI.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "client/gl/canvas.hpp"
#include "client/gl/context.hpp"
#include "client/output/frame_writer.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/coverage.hpp"
#include "client/render/painterly/video_painter.hpp"
#include "client/render/styles.hpp"
#include "common/error.hpp"
#include "common/video_source.hpp"

using namespace inkwire;

namespace {

struct Options {
  std::string gl = "osmesa", mesh, video, style = "default", pose = "thesis", view, size = "620x500", backdrop, out;
  std::vector<std::string> set;
  size_t lod = 0;
  std::string up = "auto";
  int frames = 0, fps = 0, msaa = 4;  // 0: one frame (mesh) or the whole video; 24 fps or the video's
};

// --video: paints a camera, video file or image sequence frame by frame, each over the last.
int paint_video(const Options& o) {
  if (o.style != "painterly") throw Error("--video paints with --style painterly only");
  if (o.out.empty()) throw Error("--out is required");
  VideoSource source(o.video);
  std::optional<Image> first = source.next();
  if (!first) throw Error("video '" + o.video + "' has no frames");
  const int limit = o.frames > 0 ? o.frames : source.live() ? 300 : 100000;
  auto context = create_offscreen_context(first->width, first->height, o.gl);
  Canvas canvas(first->width, first->height, 1);
  const auto painter = make_video_painter(o.set, first->width, first->height);
  canvas.bind();
  Backdrop(BackdropSpec::parse("canvas")).draw();
  FrameWriter writer(o.out, o.frames > 0 ? o.frames : 100000, o.fps > 0 ? o.fps : int(source.fps() + 0.5), false);
  int painted = 0;
  for (std::optional<Image> frame = std::move(first); frame && painted < limit; frame = source.next(), ++painted) {
    canvas.bind();
    painter->paint(*frame);
    writer.write(canvas.read());
  }
  writer.close();
  std::cerr << "inkwire-render: painted " << painted << " frames of " << o.video << " with " << painter->painter().style().brushes << " brushes\n";
  return 0;
}

glm::ivec2 parse_size(const std::string& text) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 16 || h < 16 || w > 8192 || h > 8192)
    throw Error("--size '" + text + "' is not WxH with sides 16..8192");
  return {w, h};
}

void print_styles() {
  for (const StyleInfo& s : styles()) {
    std::cout << s.name << "  -  " << s.summary << " (backdrop " << s.default_backdrop << ")\n";
    for (const ParamSpec& p : s.params()) {
      std::cout << "    " << p.name << " (" << to_string(p.type);
      if (p.type == ParamType::Float || p.type == ParamType::Int) std::cout << " " << p.min << ".." << p.max;
      if (!p.choices.empty()) {
        std::cout << (p.type == ParamType::Text ? " such as " : " ");
        for (size_t i = 0; i < p.choices.size(); ++i) std::cout << (i ? "|" : "") << p.choices[i];
      }
      std::cout << ", default " << p.default_value << "): " << p.help << "\n";
    }
  }
}

int run(const Options& o) {
  if (o.style == "list") {
    print_styles();
    return 0;
  }
  if (!o.video.empty()) return paint_video(o);
  if (o.mesh.empty()) throw Error("--mesh or --video is required");
  if (o.out.empty()) throw Error("--out is required");
  const int frames = o.frames > 0 ? o.frames : 1, fps = o.fps > 0 ? o.fps : 24;
  if (frames > 100000) throw Error("--frames must be 1..100000");
  const glm::ivec2 size = parse_size(o.size);
  const BackdropSpec backdrop_spec = BackdropSpec::parse(o.backdrop.empty() ? default_backdrop(o.style, o.set) : o.backdrop);

  SceneObject object = load_scene_object(o.mesh, o.lod, 10.0f, parse_up_axis(o.up));
  for (const std::string& w : object.warnings) std::cerr << "inkwire-render: warning: " << w << "\n";

  auto context = create_offscreen_context(size.x, size.y, o.gl);
  Canvas canvas(size.x, size.y, o.msaa);
  std::unique_ptr<Renderer> renderer = make_renderer(o.style, o.set);  // validates names and settings
  renderer->prepare(object);
  Backdrop backdrop(backdrop_spec);

  FrameState frame;
  frame.viewport = size;
  frame.backdrop = &backdrop;
  if (!o.view.empty()) {
    float az = 0, el = 0, dist = 1.4f;
    const int n = std::sscanf(o.view.c_str(), "%f,%f,%f", &az, &el, &dist);
    if (n < 2 || dist <= 0.05f || dist > 1000.0f) throw Error("--view '" + o.view + "' is not AZIMUTH,ELEVATION[,DISTANCE]");
    frame.camera = orbit_camera(object.topology.bounds, az, el, dist);
  } else if (o.pose == "thesis") {
    frame.camera = thesis_camera();
    // The study's set-up scales the object to cover about 15% of the window (SPEC G4).
    auto reference = make_renderer("default");
    reference->prepare(object);
    const float s = fit_scale_for_coverage(*reference, frame, canvas, 0.155);
    frame.model = glm::scale(glm::mat4(1.0f), glm::vec3(s));
  } else {
    throw Error("--pose '" + o.pose + "' is unknown (thesis) and no --view was given");
  }
  frame.light_direction = default_light_direction(frame.camera);
  const glm::mat4 pose = frame.model;

  FrameWriter writer(o.out, frames, fps, backdrop_spec.kind == BackdropSpec::Kind::None);
  for (int i = 0; i < frames; ++i) {
    // Animations turn the object once around its vertical axis.
    const float turn = frames > 1 ? float(2.0 * std::numbers::pi * i / frames) : 0.0f;
    frame.model = glm::rotate(glm::mat4(1.0f), turn, glm::vec3(0, 1, 0)) * pose;
    frame.frame = i;
    frame.time_seconds = double(i) / fps;
    canvas.bind();
    backdrop.draw();
    renderer->draw(frame);
    writer.write(canvas.read());
  }
  writer.close();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"inkwire-render: render one mesh in one style to PNG images or an MP4 video"};
  app.add_option("--mesh", o.mesh, "mesh file (OBJ, PLY, OFF, 3DS, ASE, glTF, ...)");
  app.add_option("--video", o.video, "paint a video instead (style painterly): a file, a folder or %04d pattern of images, camera:N or /dev/videoN");
  app.add_option("--lod", o.lod, "simplify to about this many triangles first");
  app.add_option("--up", o.up, "which of the file's axes points up: y, z, or auto (what the file or its format says: glTF Y, 3D Studio Z)")
      ->check(CLI::IsMember({"auto", "y", "z"}));
  app.add_option("--style", o.style, "style name, styles joined by '+' (drawn in turn), or 'list'");
  app.add_option("--set", o.set, "style parameter KEY=VALUE (repeatable)");
  app.add_option("--pose", o.pose, "camera pose: thesis, the fixed benchmark camera (in front of the object, slightly above, one light from the viewer)");
  app.add_option("--view", o.view, "orbit camera AZIMUTH_DEG,ELEVATION_DEG[,DISTANCE in bounding-box diagonals]");
  app.add_option("--frames", o.frames, "frames to render (the object turns once); with --video, at most this many")->check(CLI::Range(0, 100000));
  app.add_option("--fps", o.fps, "frames per second of animation time and video (default 24, or the video's)")->check(CLI::Range(0, 240));
  app.add_option("--size", o.size, "image size WxH");
  app.add_option("--msaa", o.msaa, "samples per pixel for antialiased edges (default 4; 1 = off)")->check(CLI::Range(1, 16));
  app.add_option("--backdrop", o.backdrop, "paper | paper:FILE | none (transparent) | #rrggbb; default: the style's");
  app.add_option("--gl", o.gl, "off-screen GL backend: osmesa, egl (surfaceless) or auto");
  app.add_option("--out", o.out, "output PNG, PNG pattern with %04d, or .mp4");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::cerr << "inkwire-render: " << e.what() << "\n";
    return 1;
  }
}
