#pragma once
// Screen coverage of an object (object pixels / window pixels) and the scale that brings it to a
// target, as the benchmark set-up asks (SPEC G4: about 14-17% of the window).
#include "client/gl/canvas.hpp"
#include "client/render/renderer.hpp"

namespace inkwire {

// Draws `frame` with `renderer` over a transparent clear and counts pixels with alpha > 0.
double measure_coverage(Renderer& renderer, const FrameState& frame, const Canvas& canvas);

// Returns the uniform scale for frame.model (applied on top of it) that makes the prepared
// object cover `target` of the canvas, within a few iterations of measuring.
float fit_scale_for_coverage(Renderer& renderer, FrameState frame, const Canvas& canvas, double target);

}  // namespace inkwire
