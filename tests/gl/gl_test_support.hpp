#pragma once
// Shared pieces of the headless GL tests: one OSMesa context per test process, and golden image
// comparison that writes actual and diff images on failure.
#include <string>

#include "client/gl/canvas.hpp"
#include "client/gl/context.hpp"
#include "client/render/renderer.hpp"
#include "common/image.hpp"
#include "common/mesh.hpp"

namespace inkwire::test {

// The process-wide off-screen context (made current on first use).
Context& offscreen_context();

// Clears `canvas` to `backdrop` ("none", "paper", "#rrggbb"), draws one frame, reads it back.
Image render_frame(Renderer& renderer, const FrameState& frame, const Canvas& canvas, const std::string& backdrop = "none");

// A UV sphere of unit radius, outward-facing, with `segments` around and `rings` pole to pole.
Mesh make_sphere(int segments, int rings);

// True when a covered pixel (alpha > 0) of `mask` lies within `reach` pixels of (x, y).
bool near_covered(const Image& mask, int x, int y, int reach);

// A unit cube of 12 triangles: the sharpest case for averaged vertex normals.
Mesh make_box();

// A camera on a sphere around the object for test views.
FrameState view_of(const SceneObject& object, const Canvas& canvas, float azimuth, float elevation, float distance);

struct GoldenTolerance {
  int max_channel_diff;        // a pixel counts as different above this (0..255)
  double max_different_fraction;  // fraction of pixels allowed to differ
  double max_mean_diff;        // mean absolute channel difference over the image
};

// Compares `actual` with tests/golden/<name>.png. On failure writes <name>.actual.png and
// <name>.diff.png into the test output folder and returns a description; returns "" on success.
// With INKWIRE_APPROVE_GOLDEN=1 in the environment it (over)writes the golden image instead.
std::string compare_with_golden(const Image& actual, const std::string& name, const GoldenTolerance& tolerance);

}  // namespace inkwire::test
