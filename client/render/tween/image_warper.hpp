#pragma once
// The warp engine (SPEC T3-T5), shared by the tween renderer and the face reconstruction: any
// images, any triangulated control points. A view is the control-point mesh drawn at the view's
// positions, textured from each contributing sample at that sample's own positions
// (piecewise-affine warp by texture mapping), the samples weighted and summed. Two ways:
//   one pass    every vertex carries its position in each sample and the fragment reads all
//               of them (render() into the warper's target, or draw_over() straight into the
//               caller's framebuffer);
//   per sample  the study's way: one additive pass per sample into the warper's target
//               (begin() / pass() / end()), then composite().
// Overlapping (folded) triangles must not add up twice: every pass is depth-tested with LESS at
// one depth, so the first triangle to reach a pixel is the only one written there; per-sample
// passes are either laid a little nearer each (layered) or clear depth first (depth-clear).
#include <array>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "client/gl/canvas.hpp"
#include "client/gl/resources.hpp"
#include "client/render/tween/matte_sample.hpp"
#include "common/image.hpp"
#include "common/tween/warp_mesh.hpp"

namespace inkwire {

enum class OverlapMode { Layered, DepthClear };

// One sample's part in a one-pass view.
struct WarpSource {
  const gl::Texture* image;
  int position;  // which stored position of each control point (0-2) lies in `image`
  float weight;
  float scale = 1.0f;  // texels of `image` per control-point pixel: a finer zoom level's (SPEC T18) 2, 4
};

// A sample image as the warper reads it: premultiplied alpha, linear filtering, no wrap.
gl::Texture make_sample_texture(const Image& image);

// matte_sample() of `image` as the warper reads it.
gl::Texture make_matte_texture(const Image& image, double scale = 1.0);

class ImageWarper {
 public:
  // The target (and every sample image) is `width` x `height` pixels.
  ImageWarper(int width, int height);

  // Compose one-pass views by mattes (sources made by make_matte_texture): one outline, no
  // ghost of either sample's edge. Off: the plain weighted sum (premultiplied sources).
  void set_matte(bool matte) { matte_ = matte; }

  // Uploads a mesh once; returns its handle for pass().
  int add_mesh(const WarpMesh& mesh);
  // Replaces a mesh's positions (same points and triangles, e.g. moved landmarks each frame).
  void update_mesh(int mesh, const WarpMesh& moved);
  // Replaces a mesh's triangles by the same number in another order (the first to reach a pixel
  // is the one drawn there: a turned face lays its nearest triangles first).
  void update_triangles(int mesh, std::span<const std::array<uint32_t, 3>> triangles);
  size_t triangles(int mesh) const { return meshes_.at(size_t(mesh)).index_count / 3; }

  // One pass into the warper's target (then read()): the mesh at position_weights . (p0, p1,
  // p2), each pixel the weighted sum of up to three sources read at their own positions.
  void render(int mesh, const glm::vec3& position_weights, std::span<const WarpSource> sources);
  // The same view drawn "over" the bound framebuffer into `rect` (window pixels, GL y up),
  // depth-tested and written at depth 0.5 there (the framebuffer's depth must be clear behind).
  void draw_over(int mesh, const glm::vec3& position_weights, std::span<const WarpSource> sources,
                 const glm::vec4& rect) const;

  // Per-sample passes. Starts a view: binds the target (saving the caller's framebuffer) and clears it to
  // transparent black.
  void begin(OverlapMode overlap);
  // Adds `sample` warped: vertices at position_weights . (p0, p1, p2), texels read at
  // p[source] x scale (pixels of `sample`, which may be larger than the view), colour times `weight`.
  void pass(int mesh, const gl::Texture& sample, const glm::vec3& position_weights, int source, float weight, float scale = 1.0f);
  // Ends the view and rebinds the caller's framebuffer and viewport.
  void end();

  // The last view, upright (top row first), premultiplied RGBA.
  Image read() const;
  // Draws the last view "over" the bound framebuffer into `rect` (window pixels, GL y up).
  void composite(const glm::vec4& rect) const;

 private:
  struct Mesh {
    gl::Buffer vertices, indices;
    size_t points = 0;
    gl::VertexArray vao;
    GLsizei index_count = 0;
  };
  // Draws a one-pass view with clip = pixel * to_clip.xy + to_clip.zw into the bound framebuffer.
  void blend(int mesh, const glm::vec3& position_weights, std::span<const WarpSource> sources, const glm::vec4& to_clip) const;
  const gl::Program& blend_program(size_t sources) const;
  int width_, height_;
  gl::Program warp_, composite_;
  // One program per number of sources (1-3), with and without a matte, each compiled when first
  // drawn with: a call's face warps one photo and never needs the other five, and compiling six
  // programs held up a browser's first face by about a tenth of a second.
  mutable std::array<std::optional<gl::Program>, 3> blend_, blend_matte_;
  bool matte_ = false;
  gl::Texture target_;
  gl::Renderbuffer depth_;
  gl::Framebuffer fbo_;
  gl::VertexArray empty_vao_;
  std::vector<Mesh> meshes_;
  OverlapMode overlap_ = OverlapMode::Layered;
  int passes_ = 0;
  std::unique_ptr<FramebufferBinding> caller_;
};

}  // namespace inkwire
