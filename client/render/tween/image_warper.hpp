#pragma once
// The warp engine (SPEC T3-T5), shared by the tween renderer and the face reconstruction: any
// images, any triangulated control points. A view is built in an off-screen target the size of
// the sample images by one pass per contributing sample: the control-point mesh drawn at the
// view's positions, textured from that sample at the sample's own positions (piecewise-affine
// warp by texture mapping), weighted and summed. Overlapping (folded) triangles must not add up
// twice within a pass: either each pass is laid a little nearer than the last with depth test
// LESS (layered), or depth is cleared before each pass (depth-clear).
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "client/gl/canvas.hpp"
#include "client/gl/resources.hpp"
#include "common/image.hpp"
#include "common/tween/warp_mesh.hpp"

namespace inkwire {

enum class OverlapMode { Layered, DepthClear };

// A sample image as the warper reads it: premultiplied alpha, linear filtering, no wrap.
gl::Texture make_sample_texture(const Image& image);

class ImageWarper {
 public:
  // The target (and every sample image) is `width` x `height` pixels.
  ImageWarper(int width, int height);

  // Uploads a mesh once; returns its handle for pass().
  int add_mesh(const WarpMesh& mesh);
  // Replaces a mesh's positions (same points and triangles, e.g. moved landmarks each frame).
  void update_mesh(int mesh, const WarpMesh& moved);
  size_t triangles(int mesh) const { return meshes_.at(size_t(mesh)).index_count / 3; }

  // Starts a view: binds the target (saving the caller's framebuffer) and clears it to
  // transparent black.
  void begin(OverlapMode overlap);
  // Adds `sample` warped: vertices at position_weights . (p0, p1, p2), texels read at
  // p[source] (pixels of `sample`, which may be larger than the view), colour times `weight`.
  void pass(int mesh, const gl::Texture& sample, const glm::vec3& position_weights, int source, float weight);
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
  int width_, height_;
  gl::Program warp_, composite_;
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
