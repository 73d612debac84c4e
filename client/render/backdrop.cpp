#include "client/render/backdrop.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec4.hpp>

#include "common/error.hpp"
#include "common/luminance.hpp"
#include "common/noise.hpp"
#include "common/style_params.hpp"

namespace inkwire {

using namespace gl;

BackdropSpec BackdropSpec::parse(const std::string& text) {
  BackdropSpec s;
  if (text == "paper") return s;
  if (text == "canvas") {
    s.canvas = true;
    return s;
  }
  if (text.rfind("paper:", 0) == 0) {
    s.paper_file = text.substr(6);
    if (s.paper_file.empty()) throw Error("backdrop 'paper:' needs a file name");
    return s;
  }
  if (text == "none") {
    s.kind = Kind::None;
    return s;
  }
  if (!text.empty() && text[0] == '#') {
    s.kind = Kind::Colour;
    s.colour = parse_hex_colour(text);
    return s;
  }
  throw Error("backdrop '" + text + "' is not paper, paper:FILE, canvas, none or #rrggbb");
}


Image generate_paper(int size, uint32_t seed) {
  if (size < 16 || size > 4096) throw Error("paper size must be 16..4096");
  // Octaves: broad cloudiness, medium mottling and fine grain, plus fibres: noise stretched
  // eight to one, so it reads as short streaks in the pulp rather than blotches.
  const TileableNoise broad(4, seed), mottle(16, seed + 1), grain(size / 2, seed + 2), fibre(size / 4, seed + 3);
  const glm::vec3 base = kPaperBase;
  Image img(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float u = float(x) / size, v = float(y) / size;
      float tone = 0.0f;
      tone += 0.025f * (broad.at(u * 4, v * 4) - 0.5f);
      tone += 0.030f * (mottle.at(u * 16, v * 16) - 0.5f);
      tone += 0.050f * (grain.at(u * size / 2, v * size / 2) - 0.5f);
      tone += 0.030f * (fibre.at(u * size / 4, v * size / 32) - 0.5f);
      uint8_t* p = img.at(x, y);
      for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::clamp((base[c] + tone) * 255.0f, 0.0f, 255.0f));
      p[3] = 255;
    }
  return img;
}

Image generate_canvas(int size, uint32_t seed) {
  if (size < 16 || size > 4096) throw Error("canvas size must be 16..4096");
  constexpr int kThread = 4;  // pixels per thread: a fine linen at screen scale
  const int threads = size / kThread;
  const TileableNoise slub_x(threads, seed), slub_y(threads, seed + 1), grain(size / 2, seed + 2), broad(4, seed + 3);
  const glm::vec3 base = kCanvasBase;
  Image img(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const int tx = x / kThread, ty = y / kThread;
      const float fx = (float(x % kThread) + 0.5f) / kThread, fy = (float(y % kThread) + 0.5f) / kThread;
      // Plain weave: the warp thread is on top where (tx + ty) is even, the weft elsewhere.
      const bool warp_on_top = ((tx + ty) & 1) == 0;
      const float across = warp_on_top ? fx : fy;  // position across the thread on top
      const float round = 1.0f - 4.0f * (across - 0.5f) * (across - 0.5f);  // thread's curvature
      const float slub = warp_on_top ? slub_x.at(float(tx), float(y) / kThread / 8.0f) : slub_y.at(float(x) / kThread / 8.0f, float(ty));
      float tone = 0.06f * (round - 0.6f) + 0.04f * (slub - 0.5f) + 0.03f * (grain.at(float(x) / 2, float(y) / 2) - 0.5f) +
                   0.02f * (broad.at(float(x) * 4 / size, float(y) * 4 / size) - 0.5f);
      uint8_t* p = img.at(x, y);
      for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::clamp((base[c] + tone) * 255.0f, 0.0f, 255.0f));
      p[3] = 255;
    }
  return img;
}

Backdrop::Backdrop(const BackdropSpec& spec) : spec_(spec) {
  if (spec_.kind != BackdropSpec::Kind::Paper) return;
  const Image paper = !spec_.paper_file.empty() ? load_image(spec_.paper_file) : spec_.canvas ? generate_canvas(512) : generate_paper(512);
  paper_size_ = {float(paper.width), float(paper.height)};
  // Read at one texel per pixel, at texel centres: the nearest texel is exactly what linear
  // filtering would give, for a quarter of its reads.
  paper_ = Texture::from_image(paper, {.repeat = true, .mipmaps = false, .linear = false});
  program_ = Program::from_files({"backdrop/fullscreen.vert", "backdrop/paper.frag"});
  empty_vao_ = VertexArray::create();
}

namespace {

// What draw() clears to (the paper then covers it).
glm::vec4 clear_colour(const BackdropSpec& spec) {
  const glm::vec3 c = spec.kind == BackdropSpec::Kind::Colour ? spec.colour : glm::vec3(1.0f);
  return {c, spec.kind == BackdropSpec::Kind::None ? 0.0f : 1.0f};
}

}  // namespace

void Backdrop::draw() const {
  const glm::vec4 c = clear_colour(spec_);
  glClearColor(c.r, c.g, c.b, c.a);
  glClearDepthf(1.0f);
  glClearStencil(0);
  glDepthMask(GL_TRUE);
  glStencilMask(0xff);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  if (!paper_) return;
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  program_->use();
  paper_->bind(0);
  program_->set("paper", 0);
  program_->set("paper_size", paper_size_);
  empty_vao_.bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

std::string Backdrop::under_define() const { return paper_ ? "UNDER_PAPER" : "UNDER_COLOUR"; }

void Backdrop::set_under(const gl::Program& program, GLuint unit) const {
  if (!paper_) {
    program.set("under_colour", clear_colour(spec_));
    return;
  }
  paper_->bind(unit);
  program.set("paper", int(unit));
  program.set("paper_size", paper_size_);
}

Image paper_tooth(int size) {
  const Image paper = generate_paper(size);
  std::vector<float> lum;
  double sum = 0.0, squares = 0.0;
  for (size_t i = 0; i < paper.pixels.size(); i += 4) {
    lum.push_back(rec601_luma<float>(paper.pixels[i], paper.pixels[i + 1], paper.pixels[i + 2]));
    sum += lum.back();
    squares += double(lum.back()) * lum.back();
  }
  const double mean = sum / double(lum.size()), spread = std::sqrt(std::max(squares / double(lum.size()) - mean * mean, 1e-6));
  Image tooth(paper.width, paper.height);
  for (size_t i = 0; i < lum.size(); ++i) {
    const uint8_t t = uint8_t(std::clamp(0.5 + 0.22 * (lum[i] - mean) / spread, 0.0, 1.0) * 255.0 + 0.5);
    tooth.pixels[4 * i] = tooth.pixels[4 * i + 1] = tooth.pixels[4 * i + 2] = t;
    tooth.pixels[4 * i + 3] = 255;
  }
  return tooth;
}

}  // namespace inkwire
