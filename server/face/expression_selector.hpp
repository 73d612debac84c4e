#pragma once
// Expression selection (SPEC F3): the measured features against the speaker's own neutral face
// pick a code and an intensity. classify() is the rule for one frame; ExpressionSelector adds
// the per-speaker calibration, feature smoothing and hysteresis a live stream needs so codes do
// not flicker.
#include <optional>

#include "common/face/expression.hpp"
#include "server/face/face_features.hpp"

namespace inkwire {

// Thresholds on changes from the neutral face (inter-ocular units, or ratios for the eyes).
// Defaults tuned on the development subjects 01-08 of the Yale faces only.
struct SelectionThresholds {
  // Eyes, as fractions of their neutral openness: both eyes under `eyes_closed_mean` on average
  // read as closed (people photographed "sleepy" mostly half-close them); one under
  // `wink_closed` with the other over `wink_open` is a wink; over `eyes_wide` on average they widen
  // in surprise.
  float eyes_closed_mean = 0.78f;
  float wink_closed = 0.8f;
  float wink_open = 0.8f;
  float wink_asymmetry = 0.8f;     // with a widened mouth, the shut eye under this much of the other's openness
  float broad_smile = 0.2f;        // a mouth widened this much smiles whatever one eye does (the development faces' winks widen it 0.16 at most)
  float eyes_wide = 1.08f;
  float mouth_open = 0.10f;        // inner-lip gap grown by this much: the mouth is open
  float laugh_open = 0.22f;        // a widened mouth opened this far laughs; less is a smile showing teeth
  float smile_width = 0.08f;       // relative widening of the mouth
  float smile_corner_lift = 0.05f; // (closed mouths only: opening the jaw moves the lips' midline)
  float brow_raise = 0.06f;
  float brow_lower = 0.05f;
  float round_narrowing = 0.08f;   // relative narrowing of an open mouth: rounded lips
  float sad_corner_drop = 0.03f;
  float sad_brow_tilt = 0.03f;
  float viseme_wide_open = 0.04f;  // spread lips slightly apart read as the wide viseme
};

ExpressionState classify(const FaceFeatures& face, const FaceFeatures& neutral, const SelectionThresholds& thresholds = {});

class ExpressionSelector {
 public:
  struct Options {
    int calibration_frames = 30;  // the first second at 30 fps is the neutral phase
    float smoothing = 0.5f;       // weight of the newest frame in the running features
    int hold_frames = 3;          // a new expression must win this many frames in a row (about 100 ms)
    int intensity_step = 16;      // intensity changes smaller than this are not reported
    SelectionThresholds thresholds;
  };

  ExpressionSelector() : ExpressionSelector(Options{}) {}
  explicit ExpressionSelector(Options options) : options_(options) {}

  // Calibrates at once from a known neutral face (e.g. a neutral photo) instead of the first frames.
  void calibrate(const FaceFeatures& neutral);
  bool calibrated() const { return neutral_.has_value(); }
  const std::optional<FaceFeatures>& neutral() const { return neutral_; }
  const Options& options() const { return options_; }

  // One frame's features, or nothing when no face was found (the state is kept). Returns the
  // stable state: neutral until calibrated.
  ExpressionState update(const std::optional<FaceFeatures>& features);
  ExpressionState state() const { return state_; }

 private:
  Options options_;
  std::optional<FaceFeatures> neutral_;
  FaceFeatures calibration_sum_{};
  int calibration_count_ = 0;
  std::optional<FaceFeatures> smoothed_;
  ExpressionState state_;
  Expression candidate_ = Expression::Neutral;
  int candidate_frames_ = 0;
};

}  // namespace inkwire
