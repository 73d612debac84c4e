#pragma once
// The painterly brushes as a simulation without GL (SPEC P4-P7), so motion, home-seeking,
// respawning, sizing and colour averaging are testable on plain images.
//
// Brushes live in the unit square of the capture rectangle (the screen rectangle of the object's
// projected bounding box; x right, y down, like the captured image's rows). Because that square
// moves with the object on screen, brushes follow the object without being fixed to its surface
// or to the screen: no shower-door effect.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "common/image.hpp"
#include "common/random.hpp"

namespace inkwire {

// Which pixels of the capture rectangle belong to the object (SPEC P1).
class Matte {
 public:
  Matte() = default;
  Matte(int width, int height, std::vector<uint8_t> inside);
  // Object pixels are those with alpha >= 128.
  static Matte from_alpha(const Image& image);

  int width() const { return width_; }
  int height() const { return height_; }
  // False outside the unit square: brushes that leave it count as lost (SPEC P5).
  bool covers(glm::vec2 unit) const;
  bool covers_pixel(int x, int y) const { return inside_[size_t(y) * size_t(width_) + size_t(x)] != 0; }
  double object_fraction() const { return object_fraction_; }  // P_A
  size_t object_pixels() const { return object_pixels_; }
  // Object pixels with a 4-neighbour outside the object (or outside the rectangle).
  size_t outline_pixels() const { return outline_pixels_; }
  // A uniformly random point of the unit square inside an object pixel (anywhere in the square
  // when there is none): where a lost brush starts again.
  glm::vec2 random_object_point(Random& random) const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<uint8_t> inside_;
  std::vector<uint32_t> object_indices_;  // every object pixel, row by row
  size_t object_pixels_ = 0, outline_pixels_ = 0;
  double object_fraction_ = 0;
};

struct MotionSettings {
  float max_speed = 0.004f;     // unit square per frame
  float jitter = 0.0012f;       // random acceleration added per frame (Brownian motion)
  float damping = 0.92f;        // velocity kept from one frame to the next
  int time_to_live = 10;        // frames a lost brush may search before it respawns
  bool randomise_ttl = true;    // spread respawns over frames so they do not flash in sync
};

struct Brush {
  glm::vec2 position{0}, velocity{0}, acceleration{0};
  int ttl = 0;             // frames left to find the object again; 0 while over it
  bool visible = false;    // over an object pixel this frame
  glm::vec3 colour{0};     // paint: the mean of the last few sampled colours
  float angle = 0;         // stroke direction, radians (set by the painter)
  bool styled = false;     // false until the painter has given it a look and an angle; a
                           // respawn clears it (a new place gets a new look)
};

struct StepStats {
  size_t visible = 0, respawned = 0;
};

class BrushField {
 public:
  BrushField(size_t count, const MotionSettings& motion, uint64_t seed, int colour_frames = 4);  // colour_frames 1..255

  // One frame: Brownian motion, then home-seeking against `matte` (SPEC P4, P5). A brush that
  // leaves the object turns round and gets a time-to-live; if still lost when it runs out, it
  // respawns at a random place, preferring object pixels.
  StepStats step(const Matte& matte);
  // Mixes this frame's colour under each visible brush (from `reference`, the captured image)
  // into its running mean over the last `colour_frames` frames (SPEC P7).
  void sample_colours(const Image& reference);

  const std::vector<Brush>& brushes() const { return brushes_; }
  std::vector<Brush>& brushes() { return brushes_; }
  const StepStats& last_step() const { return last_; }
  double visible_fraction() const { return brushes_.empty() ? 0.0 : double(last_.visible) / double(brushes_.size()); }
  double respawn_fraction() const { return brushes_.empty() ? 0.0 : double(last_.respawned) / double(brushes_.size()); }
  // Moves every brush to a fresh random place (a new object, a cut in a video).
  void scatter();

 private:
  int draw_ttl();
  void respawn(Brush& brush, size_t index, const Matte& matte);
  std::vector<Brush> brushes_;
  std::vector<glm::vec3> history_;  // colour_frames colours per brush, a ring
  std::vector<uint8_t> history_count_, history_next_;  // filled slots, slot to write next
  int colour_frames_;
  MotionSettings motion_;
  Random random_;
  StepStats last_;
};

// Automatic brush size (SPEC P6): with P_A the object's fraction of the capture area A (pixels)
// and `visible` brushes on it, each brush covers A_B = P_A * A / visible pixels, times an
// overlap so that neighbours overlap and `coverage` of the object is painted. Returns the side
// of a square of that area.
//
// Brushes fall like a Poisson process: a pixel stays bare with probability exp(-density), so
// the painted area must be ln(1 / (1 - coverage)) times the object's; a brush paints about the
// ellipse inscribed in its quad (pi/4 of it). 0.98 needs about 5 (overlap_for_coverage). But a
// pixel near the object's outline has brush centres on one side only: within half a brush of
// the outline it sees about 3/4 of the density. The side is grown until the interior and that
// band together leave `1 - coverage` bare, so objects with long outlines (legs, horns) stay
// covered too.
float automatic_brush_side(const Matte& matte, size_t visible, float coverage);

// The interior's overlap alone: ln(1 / (1 - coverage)) / (pi / 4).
float overlap_for_coverage(float coverage);

}  // namespace inkwire
