#include "server/face/face_analyzer.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <dlib/image_processing.h>
#include <dlib/image_processing/frontal_face_detector.h>
#include <dlib/image_transforms.h>

#include "common/error.hpp"

namespace inkwire {

struct FaceAnalyzer::Models {
  dlib::frontal_face_detector detector = dlib::get_frontal_face_detector();
  dlib::shape_predictor predictor;
};

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

dlib::array2d<unsigned char> grey_of(const Image& image) {
  dlib::array2d<unsigned char> grey(image.height, image.width);
  const uint8_t* p = image.pixels.data();
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x, p += 4) grey[y][x] = uint8_t((77 * p[0] + 150 * p[1] + 29 * p[2]) >> 8);
  return grey;
}

struct Bounds {
  float x0, y0, x1, y1;
  float width() const { return x1 - x0; }
  float height() const { return y1 - y0; }
};

Bounds bounds_of(const FaceLandmarks& points) {
  Bounds b{points[0].x, points[0].y, points[0].x, points[0].y};
  for (const glm::vec2& p : points) {
    b.x0 = std::min(b.x0, p.x), b.y0 = std::min(b.y0, p.y);
    b.x1 = std::max(b.x1, p.x), b.y1 = std::max(b.y1, p.y);
  }
  return b;
}

void check_frame(const Image& frame) {
  if (frame.width <= 0 || frame.height <= 0 || frame.pixels.size() != size_t(frame.width) * size_t(frame.height) * 4)
    throw Error("face analysis: empty or inconsistent frame");
}

FaceLandmarks place_landmarks(const dlib::shape_predictor& predictor, const dlib::array2d<unsigned char>& grey, const FaceBox& box) {
  const dlib::full_object_detection shape = predictor(grey, dlib::rectangle(box.left, box.top, box.right, box.bottom));
  FaceLandmarks out;
  for (size_t i = 0; i < out.size(); ++i) out[i] = {float(shape.part(unsigned(i)).x()), float(shape.part(unsigned(i)).y())};
  return out;
}

// Boxes in the grey frame's pixels, found on a copy reduced to `detect_width` and upsampled.
std::vector<FaceBox> detect_in(dlib::frontal_face_detector& detector, const dlib::array2d<unsigned char>& grey,
                               const FaceAnalyzerOptions& options) {
  const long width = grey.nc(), height = grey.nr();
  const double reduce = options.detect_width > 0 && width > options.detect_width ? double(options.detect_width) / double(width) : 1.0;
  dlib::array2d<unsigned char> work(std::lround(double(height) * reduce), std::lround(double(width) * reduce));
  if (reduce < 1.0) dlib::resize_image(grey, work);
  else dlib::assign_image(work, grey);
  for (int i = 0; i < options.upsample; ++i) dlib::pyramid_up(work);
  const double to_frame = 1.0 / (reduce * double(1 << options.upsample));
  std::vector<FaceBox> boxes;
  for (const dlib::rectangle& r : detector(work))
    boxes.push_back({int(double(r.left()) * to_frame), int(double(r.top()) * to_frame), int(double(r.right()) * to_frame),
                     int(double(r.bottom()) * to_frame)});
  return boxes;
}

}  // namespace

FaceAnalyzer::FaceAnalyzer(FaceAnalyzerOptions options) : models_(std::make_unique<Models>()), options_(std::move(options)) {
  if (!std::filesystem::is_regular_file(options_.model))
    throw Error("face landmark model '" + options_.model + "' not found (Debian package libdlib-data)");
  try {
    dlib::deserialize(options_.model) >> models_->predictor;
  } catch (const std::exception& e) {
    throw Error("face landmark model '" + options_.model + "' is unreadable: " + e.what());
  }
  if (models_->predictor.num_parts() != kFaceLandmarks)
    throw Error("face landmark model '" + options_.model + "' has " + std::to_string(models_->predictor.num_parts()) +
                " points, not 68");
}

FaceAnalyzer::~FaceAnalyzer() = default;
FaceAnalyzer::FaceAnalyzer(FaceAnalyzer&&) noexcept = default;
FaceAnalyzer& FaceAnalyzer::operator=(FaceAnalyzer&&) noexcept = default;

void FaceAnalyzer::reset() {
  tracked_.reset();
  frames_since_detection_ = 0;
}

std::vector<FaceBox> FaceAnalyzer::detect(const Image& frame) {
  check_frame(frame);
  return detect_in(models_->detector, grey_of(frame), options_);
}

std::vector<FaceBox> FaceAnalyzer::detect_in_photo(const Image& photo) {
  check_frame(photo);
  // The detector finds faces from about 80 pixels up: a photo up to 2000 pixels wide is searched
  // whole (a face a twentieth of a group photo's width is found), a larger one reduced to that,
  // and one under 1000 pixels also doubled (its small faces).
  const int width = photo.width;
  FaceAnalyzerOptions whole = options_;
  whole.detect_width = std::min(width, 2000);
  whole.upsample = width < 1000 ? 1 : 0;
  std::vector<FaceBox> boxes = detect_in(models_->detector, grey_of(photo), whole);
  std::sort(boxes.begin(), boxes.end(), [](const FaceBox& a, const FaceBox& b) { return a.left < b.left; });
  return boxes;
}

FaceLandmarks FaceAnalyzer::landmarks_in(const Image& frame, const FaceBox& box) {
  check_frame(frame);
  return place_landmarks(models_->predictor, grey_of(frame), box);
}

std::optional<FaceAnalysis> FaceAnalyzer::analyse(const Image& frame) {
  check_frame(frame);
  const dlib::array2d<unsigned char> grey = grey_of(frame);
  detect_ms_ = 0;
  const bool detecting = !tracked_ || frames_since_detection_ + 1 >= std::max(options_.detect_every, 1);

  FaceBox box;
  if (detecting) {
    const auto start = Clock::now();
    const std::vector<FaceBox> faces = detect_in(models_->detector, grey, options_);
    detect_ms_ = ms_since(start);
    if (faces.empty()) {
      reset();
      return std::nullopt;
    }
    box = *std::max_element(faces.begin(), faces.end(), [](const FaceBox& a, const FaceBox& b) { return a.width() < b.width(); });
    frames_since_detection_ = 0;
  } else {
    // Track: the detector's box where the last landmarks are, as it sat around them when found.
    const Bounds b = bounds_of(*tracked_);
    const float size = box_scale_ * b.width();
    const float cx = 0.5f * (b.x0 + b.x1) + box_dx_ * b.width(), cy = 0.5f * (b.y0 + b.y1) + box_dy_ * b.width();
    box = {int(cx - 0.5f * size), int(cy - 0.5f * size), int(cx + 0.5f * size), int(cy + 0.5f * size)};
    ++frames_since_detection_;
  }

  FaceAnalysis out{place_landmarks(models_->predictor, grey, box), detecting};

  const Bounds b = bounds_of(out.landmarks);
  if (b.width() < 8.0f || b.x1 < 0 || b.y1 < 0 || b.x0 > float(frame.width) || b.y0 > float(frame.height)) {
    reset();  // lost: detect again next frame
    return std::nullopt;
  }
  if (detecting) {
    box_scale_ = float(box.width()) / b.width();
    box_dx_ = (0.5f * float(box.left + box.right) - 0.5f * (b.x0 + b.x1)) / b.width();
    box_dy_ = (0.5f * float(box.top + box.bottom) - 0.5f * (b.y0 + b.y1)) / b.width();
  }
  tracked_ = out.landmarks;
  return out;
}

}  // namespace inkwire
