#pragma once
// Uncertainty functions (SPEC S2): lines that look drawn by hand.
//
// Recursive midpoint displacement: a line longer than the maximum segment (compared as squared
// lengths) is split at its midpoint, moved sideways by a random amount, and each half is
// treated the same way with half the amplitude. Endpoints are offset too, so strokes overshoot
// or stop short. The amplitude is proportional to the edge's length but clamped to a threshold
// taken from the bounding box, so small and large objects and very long edges all look right.
// Every point stays within `amplitude` of the true edge: endpoints move at most a quarter of it,
// and the midpoint displacements (a quarter, then halving) add up to less than a half.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "common/random.hpp"

namespace inkwire {

// Sketch strokes draw their randomness from the shared deterministic generator.
using StrokeRandom = Random;
inline uint64_t stroke_seed(uint64_t a, uint64_t b, uint64_t c = 0) { return mix_seed(a, b, c); }

struct PerturbOptions {
  float max_segment = 0.05f;     // split lines longer than this (mesh units)
  float amplitude_ratio = 0.04f; // sideways amplitude as a fraction of the edge's length...
  float amplitude_clamp = 0.02f; // ...but never more than this (mesh units, from the bounds)
};

// The amplitude for an edge of `length`.
inline float perturb_amplitude(float length, const PerturbOptions& o) {
  return std::min(length * o.amplitude_ratio, o.amplitude_clamp);
}

// Appends a perturbed polyline from a to b (its points, in order) to `out`. `side` is the
// direction points move in (unit, across the edge as seen by the viewer).
void perturb_edge(const glm::vec3& a, const glm::vec3& b, const glm::vec3& side, const PerturbOptions& options,
                  StrokeRandom& random, std::vector<glm::vec3>& out);

// The same for a whole stroke (a chain of edges, at least two points): segments longer than
// the maximum are split first (squared-length tests), then one sideways offset per point is
// made by midpoint displacement over the stroke's length, so a long stroke wobbles as a whole.
// `sides` holds each point's unit sideways direction; the amplitude follows the stroke's
// length. Every point stays within that amplitude of the stroke.
void perturb_stroke(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& sides, const PerturbOptions& options,
                    StrokeRandom& random, std::vector<glm::vec3>& out);

}  // namespace inkwire
