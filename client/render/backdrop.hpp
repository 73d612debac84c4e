#pragma once
// Custom clear (SPEC G6): instead of a flat colour, a tileable paper texture drawn full-screen
// with no depth test and no lighting, then objects over it. Also the flat and transparent
// clears, so every program chooses its backdrop the same way
// (--backdrop paper|canvas|none|#rrggbb; paintings default to canvas).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "client/gl/resources.hpp"
#include "common/image.hpp"

namespace inkwire {

struct BackdropSpec {
  enum class Kind { Paper, None, Colour } kind = Kind::Paper;
  glm::vec3 colour{1.0f};
  std::filesystem::path paper_file;  // empty: generated paper (or canvas)
  bool canvas = false;               // generated woven canvas instead of paper

  // "paper", "paper:FILE", "canvas", "none" or "#rrggbb". Throws inkwire::Error otherwise.
  static BackdropSpec parse(const std::string& text);
};

// The generated paper's and canvas's base colours (0..1): what a drawn face's ground is laid in.
inline const glm::vec3 kPaperBase(0.965f, 0.945f, 0.905f);   // warm off-white
inline const glm::vec3 kCanvasBase(0.90f, 0.87f, 0.80f);     // primed linen

// A tileable paper texture: warm off-white with fibres and grain at several scales, wrapping
// seamlessly at its edges. Deterministic for a given seed.
Image generate_paper(int size, uint32_t seed = 1);
// The generated paper's grain as a tooth map (grey, tileable): its luminance centred on its mean
// and scaled by its spread, so raised fibres (lighter) lie near 1 and valleys near 0. Dry media
// catch the raised fibres; wet pigment settles in the valleys.
Image paper_tooth(int size);
// A primed linen canvas: over-and-under threads with slubs, tileable like the paper.
Image generate_canvas(int size, uint32_t seed = 1);

class Backdrop {
 public:
  explicit Backdrop(const BackdropSpec& spec);
  // Clears colour, depth and stencil, then draws the backdrop into the bound framebuffer.
  void draw() const;
  // For a surface that draws the backdrop under its own see-through ink in one opaque pass
  // (instead of laying depth first and blending): the shader's #define ("UNDER_PAPER" or
  // "UNDER_COLOUR"), then its uniforms: "under_colour" (rgba, alpha 0 for "none"), or "paper"
  // (on texture unit `unit`) and "paper_size", read exactly as draw() reads them.
  std::string under_define() const;
  void set_under(const gl::Program& program, GLuint unit) const;
  const BackdropSpec& spec() const { return spec_; }

 private:
  BackdropSpec spec_;
  std::optional<gl::Texture> paper_;
  std::optional<gl::Program> program_;
  gl::VertexArray empty_vao_;  // core profile needs a bound VAO even for attribute-less draws
  glm::vec2 paper_size_{0.0f};  // texels
};

}  // namespace inkwire
