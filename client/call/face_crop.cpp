#include "client/call/face_crop.hpp"

#include <algorithm>
#include <cmath>

namespace inkwire {
namespace {

constexpr double kJumpMove = 0.5, kJumpScale = 1.5;  // of the shown side: start the video again

// The square of the region's longer side about its centre, moved into the frame.
protocol::FaceRegion squared(const protocol::FaceRegion& r, int frame_width, int frame_height) {
  const int side = std::min({int(std::max(r.width, r.height)), frame_width, frame_height});
  const int x = std::clamp(int(r.x) + int(r.width) / 2 - side / 2, 0, frame_width - side);
  const int y = std::clamp(int(r.y) + int(r.height) / 2 - side / 2, 0, frame_height - side);
  return {.found = true, .x = uint16_t(x), .y = uint16_t(y), .width = uint16_t(side), .height = uint16_t(side)};
}

}  // namespace

FaceCropChoice follow_face(const protocol::FaceRegion& shown, const protocol::FaceRegion& reported_region, int frame_width, int frame_height) {
  const protocol::FaceRegion reported = squared(reported_region, frame_width, frame_height);
  if (!shown.found) return {.region = reported, .jumped = true};
  const double side = std::max(1.0, double(std::max(shown.width, shown.height)));
  const double dx = (double(reported.x) + reported.width / 2.0) - (double(shown.x) + shown.width / 2.0);
  const double dy = (double(reported.y) + reported.height / 2.0) - (double(shown.y) + shown.height / 2.0);
  const double move = std::hypot(dx, dy) / side;
  const double scale = double(std::max(reported.width, reported.height)) / side;
  const double grown = std::max(scale, 1.0 / std::max(scale, 1e-6));
  return {.region = reported, .jumped = move > kJumpMove || grown > kJumpScale};
}

PictureSize search_picture_size(int frame_width, int frame_height) {
  const double scale = std::min(1.0, double(kFaceSearchWidth) / std::max(frame_width, frame_height));
  const auto even = [&](int side) { return std::max(16, int(std::lround(side * scale / 2)) * 2); };
  return {even(frame_width), even(frame_height)};
}

}  // namespace inkwire
