#pragma once
// Tween data (SPEC T3, T6): control points that move between sample images, and their compact
// binary codec. What the server streams to clients beside the sample photos (a few hundred
// bytes per sample pair), and what the tween renderer and the face reconstruction warp by.
//
// A *cell* is two or three samples that views between them are synthesised from:
// - a pair (a, b): each control point is a path of three positions: in sample a, in the view
//   halfway from a to b, in sample b (the study's "3 2D points per point and sample pair");
// - a triangle (a, b, c) of a view sphere: each point's positions in a, b and c.
// Positions are image pixels (x right, y down, origin at the top-left corner of the image).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace inkwire {

using ControlPoint = std::array<glm::vec2, 3>;

struct TweenCell {
  std::vector<uint16_t> samples;  // 2 (pair) or 3 (triangle) distinct sample indices
  std::vector<ControlPoint> points;

  bool is_pair() const { return samples.size() == 2; }
  bool operator==(const TweenCell&) const = default;
};

struct TweenData {
  int width = 0, height = 0;  // the sample images' size in pixels
  // Per sample, the unit direction from the object's centre toward the camera that took it,
  // in the object's frame (azimuth about +Y from +Z, as orbit cameras). Travels as 3 x i16.
  std::vector<glm::vec3> directions;
  std::vector<TweenCell> cells;

  int sample_count() const { return int(directions.size()); }

  bool operator==(const TweenData&) const = default;
};

// Coordinates travel as 16-bit fixed point with 4 fractional bits: 1/16 pixel, images up to
// 4095 pixels a side.
inline constexpr int kTweenFractionBits = 4;
inline constexpr int kMaxTweenImageSide = 4095;
inline constexpr int kMaxTweenSamples = 4096;
inline constexpr int kMaxTweenCells = 16384;
inline constexpr int kMaxTweenPointsPerCell = 4096;
inline constexpr size_t kMaxTweenBytes = 8u << 20;

// Rounds every position and direction to what the codec carries (1/16 pixel, clamped to the
// image; direction components to 1/32767).
TweenData quantised(const TweenData& data);

// The versioned binary form. Lossless with respect to quantised(): decode(encode(d)) ==
// quantised(d). Throws inkwire::Error if `data` breaks the limits above (sizes, indices).
std::vector<uint8_t> encode_tween(const TweenData& data);
// Throws inkwire::Error with a one-line reason on truncated, oversized, malformed or
// inconsistent input (bad magic or version, indices out of range, points outside the image,
// trailing bytes).
TweenData decode_tween(std::span<const uint8_t> bytes);

// One cell alone, as a `tween-data` message carries it (protocol/SPEC.md): the cell layout of
// the full form, read against the product's image size and sample count, which travel apart.
// Lossless with respect to quantised(). Both throw inkwire::Error as the full form does.
inline constexpr size_t kMaxTweenCellBytes = 16 * 1024;
std::vector<uint8_t> encode_tween_cell(const TweenCell& cell, int width, int height, int samples);
TweenCell decode_tween_cell(std::span<const uint8_t> bytes, int width, int height, int samples);

// Where a pair's control point is at t in [0, 1] (0 = sample a, 1 = sample b): the quadratic
// Bézier through the halfway position at t = 0.5. Written as weights of the three stored
// positions, so a shader can evaluate it as one weighted sum.
glm::vec3 path_weights(float t);
glm::vec2 path_position(const ControlPoint& p, float t);

}  // namespace inkwire
