#include "client/render/painterly/brush_field.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "common/error.hpp"

namespace inkwire {

Matte::Matte(int width, int height, std::vector<uint8_t> inside) : width_(width), height_(height), inside_(std::move(inside)) {
  if (width <= 0 || height <= 0 || inside_.size() != size_t(width) * size_t(height))
    throw Error("Matte: " + std::to_string(inside_.size()) + " values for " + std::to_string(width) + "x" + std::to_string(height) + " pixels");
  for (size_t i = 0; i < inside_.size(); ++i)
    if (inside_[i]) object_indices_.push_back(uint32_t(i));
  object_pixels_ = object_indices_.size();
  for (const uint32_t i : object_indices_) {
    const int x = int(i % uint32_t(width)), y = int(i / uint32_t(width));
    const bool edge = x == 0 || y == 0 || x == width - 1 || y == height - 1 || !covers_pixel(x - 1, y) || !covers_pixel(x + 1, y) ||
                      !covers_pixel(x, y - 1) || !covers_pixel(x, y + 1);
    outline_pixels_ += edge;
  }
  object_fraction_ = double(object_pixels_) / double(inside_.size());
}

Matte Matte::from_alpha(const Image& image) {
  std::vector<uint8_t> inside(size_t(image.width) * size_t(image.height));
  for (size_t i = 0; i < inside.size(); ++i) inside[i] = image.pixels[i * 4 + 3] >= 128;
  return Matte(image.width, image.height, std::move(inside));
}

bool Matte::covers(glm::vec2 unit) const {
  if (!(unit.x >= 0.0f && unit.x < 1.0f && unit.y >= 0.0f && unit.y < 1.0f)) return false;  // NaN too
  return covers_pixel(std::min(int(unit.x * float(width_)), width_ - 1), std::min(int(unit.y * float(height_)), height_ - 1));
}

glm::vec2 Matte::random_object_point(Random& random) const {
  if (object_indices_.empty()) return {random.uniform(0, 1), random.uniform(0, 1)};
  const uint32_t i = object_indices_[size_t(random.next() % object_indices_.size())];
  // Braces, not parentheses: the draws then happen in order whatever the compiler (the browser's
  // module and the native client paint the same strokes; function arguments have no order).
  const glm::vec2 pixel{float(i % uint32_t(width_)) + random.uniform(0, 1), float(i / uint32_t(width_)) + random.uniform(0, 1)};
  return glm::min(pixel / glm::vec2(width_, height_), glm::vec2(std::nextafter(1.0f, 0.0f)));
}

BrushField::BrushField(size_t count, const MotionSettings& motion, uint64_t seed, int colour_frames)
    : brushes_(count),
      history_(count * size_t(std::clamp(colour_frames, 1, 255))),
      history_count_(count, 0),
      history_next_(count, 0),
      colour_frames_(std::clamp(colour_frames, 1, 255)),
      motion_(motion),
      random_(seed) {
  scatter();
}

void BrushField::scatter() {
  for (Brush& b : brushes_) {
    b = Brush{};
    b.position = {random_.uniform(0, 1), random_.uniform(0, 1)};
    b.velocity = {random_.uniform(-1, 1) * motion_.max_speed * 0.5f, random_.uniform(-1, 1) * motion_.max_speed * 0.5f};
  }
  std::fill(history_count_.begin(), history_count_.end(), uint8_t(0));
  std::fill(history_next_.begin(), history_next_.end(), uint8_t(0));
}

int BrushField::draw_ttl() {
  const int ttl = std::max(motion_.time_to_live, 1);
  // Uniform over 1..2*ttl-1 keeps the mean while spreading respawns over many frames.
  return motion_.randomise_ttl ? random_.between(1, 2 * ttl - 1) : ttl;
}

void BrushField::respawn(Brush& b, size_t index, const Matte& matte) {
  // A random place on the object: a respawned brush paints at once.
  b.position = matte.random_object_point(random_);
  b.velocity = {random_.uniform(-1, 1) * motion_.max_speed * 0.5f, random_.uniform(-1, 1) * motion_.max_speed * 0.5f};
  b.acceleration = {0, 0};
  b.ttl = 0;
  b.styled = false;
  history_count_[index] = 0;  // a new place: forget the old paint
  history_next_[index] = 0;
}

StepStats BrushField::step(const Matte& matte) {
  StepStats stats;
  for (size_t i = 0; i < brushes_.size(); ++i) {
    Brush& b = brushes_[i];
    b.acceleration = b.acceleration * 0.5f + glm::vec2{random_.uniform(-1, 1), random_.uniform(-1, 1)} * motion_.jitter;  // in order (braces)
    b.velocity = b.velocity * motion_.damping + b.acceleration;
    const float speed = glm::length(b.velocity);
    if (speed > motion_.max_speed) b.velocity *= motion_.max_speed / speed;
    b.position += b.velocity;
    if (matte.covers(b.position)) {
      b.ttl = 0;
    } else if (b.ttl == 0) {  // just lost: turn round and search for a while
      b.velocity = -b.velocity;
      b.acceleration = -b.acceleration;
      b.ttl = draw_ttl();
    } else if (--b.ttl == 0) {
      respawn(b, i, matte);
      ++stats.respawned;
    }
    b.visible = matte.covers(b.position);
    if (b.visible) {
      b.ttl = 0;
      ++stats.visible;
    } else {
      if (b.ttl == 0) b.ttl = draw_ttl();  // respawned off the object: lost from the start
    }
  }
  last_ = stats;
  return stats;
}

void BrushField::sample_colours(const Image& reference) {
  if (reference.empty()) return;
  const size_t k = size_t(colour_frames_);
  for (size_t i = 0; i < brushes_.size(); ++i) {
    Brush& b = brushes_[i];
    if (!b.visible) continue;
    // The mean of the object pixels in a 3x3 neighbourhood: one noisy pixel does not decide.
    const int cx = std::clamp(int(b.position.x * float(reference.width)), 0, reference.width - 1);
    const int cy = std::clamp(int(b.position.y * float(reference.height)), 0, reference.height - 1);
    glm::vec3 sum{0};
    int n = 0;
    for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, reference.height - 1); ++y)
      for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, reference.width - 1); ++x) {
        const uint8_t* p = reference.at(x, y);
        if (p[3] < 128) continue;
        sum += glm::vec3(p[0], p[1], p[2]);
        ++n;
      }
    if (n == 0) continue;
    glm::vec3* ring = &history_[i * k];
    ring[history_next_[i]] = sum / (255.0f * float(n));
    history_next_[i] = uint8_t((history_next_[i] + 1u) % k);
    history_count_[i] = uint8_t(std::min<size_t>(history_count_[i] + 1u, k));
    glm::vec3 mean{0};
    for (size_t j = 0; j < history_count_[i]; ++j) mean += ring[j];  // the first `count` slots are filled
    b.colour = mean / float(history_count_[i]);
  }
}

float automatic_brush_side(const Matte& matte, size_t visible, float coverage) {
  const double object_pixels = double(matte.object_pixels());
  if (object_pixels == 0) return 1.0f;
  const double per_brush = object_pixels / double(std::max<size_t>(visible, 1));  // A_B before overlap
  const double bare_wanted = 1.0 - std::clamp(double(coverage), 0.01, 0.9999);
  auto bare = [&](double side) {
    const double density = (3.14159265 / 4.0) * side * side / per_brush;
    const double band = std::min(1.0, double(matte.outline_pixels()) * side / 2.0 / object_pixels);
    return (1.0 - band) * std::exp(-density) + band * std::exp(-0.75 * density);
  };
  // From the interior's size up: bare area falls as the side grows.
  double lo = std::sqrt(per_brush * double(overlap_for_coverage(coverage))), hi = lo;
  while (bare(hi) > bare_wanted && hi < 64.0 * lo) hi *= 1.25;
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    (bare(mid) > bare_wanted ? lo : hi) = mid;
  }
  return float(hi);
}

float overlap_for_coverage(float coverage) {
  const float c = std::clamp(coverage, 0.01f, 0.9999f);
  return -std::log(1.0f - c) / (3.14159265f / 4.0f);
}

}  // namespace inkwire
