#pragma once
// The web-scene suite's platform references: the least GL a frame of two kinds of work can be,
// timed natively here and, with the same data, shaders and calls written by hand in script, in
// the browser (tests/web/web_scene_bench.py). Their ratios are what the browser's WebGL2 costs
// before any of the module's work: the ceiling of the styles' ratios to native.
//   bare-mesh:  a clear and one indexed draw of a 5 832-triangle sphere, back faces culled, as
//               the default style draws the cow;
//   bare-quads: a clear and 1 500 blended 40-pixel quads in one instanced draw, as the
//               painterly style draws its brushes.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "client/gl/resources.hpp"
#include "client/render/renderer.hpp"

namespace inkwire::bench {

class BareFrame final : public Renderer {
 public:
  enum class Kind { Mesh, Quads };
  explicit BareFrame(Kind kind);
  std::string name() const { return kind_ == Kind::Mesh ? "bare-mesh" : "bare-quads"; }
  void configure(const StyleParams&) override {}
  void prepare(const SceneObject&) override {}
  void draw(const FrameState& frame) override;
  // What the page draws the same from: {name, vertex, fragment, positions and indices (mesh) or
  // centres and half_size (quads)}.
  nlohmann::json page_json() const;

 private:
  Kind kind_;
  std::vector<float> positions_;   // mesh: x, y, z per vertex; quads: x, y per centre
  std::vector<uint16_t> indices_;  // mesh only
  std::string vertex_source_, fragment_source_;
  gl::Program program_;
  gl::VertexArray vertex_array_;
  gl::Buffer vertices_, index_buffer_;
};

// The frame's turn of the sphere and move of the quads: the page's are the same.
inline float bare_frame_angle(long frame) { return 0.02f * float(frame); }
inline float bare_frame_shift(long frame) { return float(frame % 8); }
inline constexpr float kBareQuadHalfSize = 20.0f;
inline constexpr int kBareQuads = 1500;

}  // namespace inkwire::bench
