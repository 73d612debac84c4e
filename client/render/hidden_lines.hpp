#pragma once
// Hidden-line removal that keeps the backdrop (SPEC G7): lay the filled triangles into the
// depth buffer only (colour writes masked), then draw lines with a less-or-equal depth test.
// With several objects, lay every object's depth first, then draw every object's lines.
#include <glm/mat4x4.hpp>

#include "client/gl/resources.hpp"
#include "client/render/gpu_mesh.hpp"
#include "client/render/renderer.hpp"

namespace inkwire {

// Lines drawn between these (wide lines, client/render/wide_lines.hpp) blend by their pixel
// coverage, so they look smooth without multisampling; alpha accumulates too, so ink over a transparent backdrop stays
// visible. end_smooth_lines() leaves blending off.
void begin_smooth_lines();
void end_smooth_lines();

class HiddenLineRemoval {
 public:
  HiddenLineRemoval();
  // Pass 1 for one object, unless the frame says its depth is laid already. The depth is pushed
  // back slightly (polygon offset) so lines lying on the surface win the less-or-equal test
  // instead of stitching with it.
  void lay_depth(const GpuMesh& mesh, const FrameState& frame) const;
  // Pass 1's depth state for a surface that is drawn in colour at the same time (opaque
  // hatching): its depth then serves any lines drawn over it exactly as lay_depth()'s would.
  static void begin_surface_depth();
  static void end_surface_depth();
  // Pass 2 state: colour writes on, depth test less-or-equal, depth writes off, ink blended
  // over what is there by its alpha and lines by their coverage (begin_smooth_lines).
  static void begin_lines();
  // Back to the usual state (depth writes on, depth test less, no blending).
  static void end_lines();

 private:
  gl::Program depth_only_;
};

}  // namespace inkwire
