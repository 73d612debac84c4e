#include "client/call/face_crop.hpp"

#include <algorithm>
#include <cmath>

namespace inkwire {
namespace {

constexpr double kDriftMove = 0.1, kDriftScale = 1.15;  // of the shown side: move the crop
constexpr double kJumpMove = 0.5, kJumpScale = 1.5;     // ... start the video again

}  // namespace

FaceCropChoice follow_face(const protocol::FaceRegion& shown, const protocol::FaceRegion& reported) {
  if (!shown.found) return {.region = reported, .jumped = true};
  const double side = std::max(1.0, double(std::max(shown.width, shown.height)));
  const double dx = (double(reported.x) + reported.width / 2.0) - (double(shown.x) + shown.width / 2.0);
  const double dy = (double(reported.y) + reported.height / 2.0) - (double(shown.y) + shown.height / 2.0);
  const double move = std::hypot(dx, dy) / side;
  const double scale = double(std::max(reported.width, reported.height)) / side;
  const double grown = std::max(scale, 1.0 / std::max(scale, 1e-6));
  if (move > kJumpMove || grown > kJumpScale) return {.region = reported, .jumped = true};
  if (move > kDriftMove || grown > kDriftScale) return {.region = reported, .jumped = false};
  return {.region = shown, .jumped = false};
}

}  // namespace inkwire
