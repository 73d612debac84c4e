#pragma once
// Face analysis (SPEC F2): find the face in a frame and its 68 landmarks. Detection (dlib's HOG
// frontal face detector, on a reduced copy of the frame for speed) runs every n-th frame; in
// between the face is tracked by placing the landmark model's box where the last landmarks
// were, which costs a millisecond instead of tens. The landmark model is dlib's 68-point shape
// predictor from Debian's libdlib-data.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/face/face_shape.hpp"
#include "common/image.hpp"

namespace inkwire {

// Where Debian's libdlib-data installs the 68-point model.
constexpr const char* kDefaultFaceModel = "/usr/share/dlib/shape_predictor_68_face_landmarks.dat";

struct FaceAnalyzerOptions {
  int detect_every = 5;     // frames; 1 detects on every frame
  int detect_width = 320;   // frames wider than this are reduced to it for detection (0: never)
  int upsample = 0;         // detector pyramid upsampling, for faces under ~80 px at detection size
  std::string model = kDefaultFaceModel;
};

// A face's box in frame pixels.
struct FaceBox {
  int left = 0, top = 0, right = 0, bottom = 0;  // inclusive
  int width() const { return right - left + 1; }
  int height() const { return bottom - top + 1; }
};

struct FaceAnalysis {
  FaceLandmarks landmarks;
  bool detected = false;  // found by the detector this frame (else tracked)
};

class FaceAnalyzer {
 public:
  // Loads the landmark model (~0.4 s); throws inkwire::Error when it is missing or unreadable.
  explicit FaceAnalyzer(FaceAnalyzerOptions options = {});
  ~FaceAnalyzer();
  FaceAnalyzer(FaceAnalyzer&&) noexcept;
  FaceAnalyzer& operator=(FaceAnalyzer&&) noexcept;

  // The largest face's landmarks, or nothing when there is no face. Throws on empty frames.
  std::optional<FaceAnalysis> analyse(const Image& frame);
  // The detector alone (reduced and upsampled as the options say), boxes in frame pixels.
  std::vector<FaceBox> detect(const Image& frame);
  // Every face in a still photo, large or small: the detector run at a scale that fits the
  // photo (a group photo's small faces at full resolution, a small photo upsampled), not on the
  // reduced copy video frames use. Boxes in photo pixels, left to right.
  std::vector<FaceBox> detect_in_photo(const Image& photo);
  // The landmark model alone, placed in `box`.
  FaceLandmarks landmarks_in(const Image& frame, const FaceBox& box);

  // Forgets the tracked face: the next frame runs the detector.
  void reset();

  // Time the last analyse() spent detecting (0 when it tracked).
  double last_detect_ms() const { return detect_ms_; }

 private:
  struct Models;
  std::unique_ptr<Models> models_;
  FaceAnalyzerOptions options_;
  int frames_since_detection_ = 0;
  std::optional<FaceLandmarks> tracked_;
  // The detector's box relative to the landmarks' bounding box at the last detection.
  float box_scale_ = 1, box_dx_ = 0, box_dy_ = 0;
  double detect_ms_ = 0;
};

}  // namespace inkwire
