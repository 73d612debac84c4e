#pragma once
// The web-scene suite's platform reference: the least GL a frame can be (a clear and one indexed
// draw of a 5 832-triangle sphere, back faces culled), timed natively here and, with the same
// triangles, shaders and calls written by hand in script, in the browser
// (tests/web/web_scene_bench.py). Its ratio is what the browser's WebGL2 costs before any of the
// module's work: the ceiling of every style's ratio to native.
#include <cstdint>
#include <string>
#include <vector>

#include "client/gl/resources.hpp"
#include "client/render/renderer.hpp"

namespace inkwire::bench {

class BareSphere final : public Renderer {
 public:
  BareSphere();
  void configure(const StyleParams&) override {}
  void prepare(const SceneObject&) override {}
  void draw(const FrameState& frame) override;
  // Triangles, vertices and shader sources as JSON, for the page to draw the same.
  std::string page_json() const;

 private:
  std::vector<float> positions_;
  std::vector<uint16_t> indices_;
  std::string vertex_source_, fragment_source_;
  gl::Program program_;
  gl::VertexArray vertex_array_;
  gl::Buffer vertices_, index_buffer_;
};

// The frame's angle: the page turns the same.
inline float bare_sphere_angle(long frame) { return 0.02f * float(frame); }

}  // namespace inkwire::bench
