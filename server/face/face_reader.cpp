#include "server/face/face_reader.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "server/face/face_features.hpp"
#include "server/face/head_pose.hpp"

namespace inkwire {
namespace {

// How far a template's inner lips part at full intensity (inter-ocular units).
float template_opening(Expression e) {
  const auto& offsets = shipped_templates().offsets[size_t(e)];
  if (!offsets) return 0.0f;
  float gap = 0;
  for (const auto& [upper, lower] : {std::pair{61, 67}, std::pair{62, 66}, std::pair{63, 65}})
    gap += ((*offsets)[size_t(lower)].y - (*offsets)[size_t(upper)].y) / 3.0f;
  return gap;
}

uint8_t amount(float value) { return uint8_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

void FaceReader::calibrate(const FaceLandmarks& neutral, const Image* photo) {
  selector_.calibrate(measure_features(neutral, photo));
  neutral_ = neutral;
  state_ = {};
}

const FaceState& FaceReader::read(const std::optional<FaceLandmarks>& landmarks, const Image* picture, const FaceLandmarks* in_frame) {
  const std::optional<FaceFeatures> features = landmarks ? std::optional(measure_features(*landmarks, picture)) : std::nullopt;
  const ExpressionState expression = selector_.update(features);
  if (!landmarks) return state_;
  const FaceLandmarks& posed = in_frame ? *in_frame : *landmarks;
  if (!neutral_) neutral_ = posed;
  if (selector_.neutral()) {
    read_layers(*features, expression);
    read_eyes(*features, expression.expression);
  } else {
    const FaceLayers calibrating = layers_of(expression);  // neutral until calibrated
    state_.layers.expression = calibrating.expression, state_.layers.mouth = calibrating.mouth;
  }
  state_.pose = head_pose(posed, *neutral_);
  return state_;
}

void FaceReader::read_layers(const FaceFeatures& f, ExpressionState code) {
  const FaceFeatures& neutral = *selector_.neutral();
  // The expression: the selector's code without what the mouth and eyes say (a laugh is a smile
  // with its mouth open; shut eyes and visemes leave the face as it was).
  ExpressionState face{};
  switch (code.expression) {
    case Expression::Smile:
    case Expression::Frown:
    case Expression::Surprise:
    case Expression::Sad: face = code; break;
    case Expression::Laugh: face = {Expression::Smile, std::max<uint8_t>(code.intensity, 160)}; break;
    default: break;
  }
  state_.layers.expression = face;
  // The mouth: opened further than the expression's own mouth opens it (a viseme over it, rounded
  // when the lips narrow), or less (drawn back to rest), or as it (its own). The opening lightly
  // steadied (half the newest picture), so the syllables' mouths come through, and in steps of a
  // quarter that change once it is a step and a half away, so the landmarks' jitter sends nothing.
  const float opening = f.mouth_open - neutral.mouth_open, widening = f.mouth_width / std::max(neutral.mouth_width, 1e-3f) - 1.0f;
  opening_ = opening_ ? 0.5f * opening + 0.5f * *opening_ : opening;
  const float own = template_opening(face.expression) * float(face.intensity) / 255.0f, full = template_opening(Expression::VisemeOpen);
  float wanted = 0;  // the mouth layer's amount, signed: > 0 opened over its own, < 0 back to rest
  if (*opening_ > own + kMouthMargin) wanted = (*opening_ - own) / full;
  else if (own > kMouthMargin && *opening_ < own - kMouthMargin) wanted = -(own - *opening_) / own;
  const float step = 0.25f;
  if (std::abs(wanted - mouth_level_) >= 0.6f * step) mouth_level_ = std::round(wanted / step) * step;
  if (mouth_level_ > 0) {
    const SelectionThresholds& t = selector_.options().thresholds;
    state_.layers.mouth = {widening < -t.round_narrowing ? Expression::VisemeRound : Expression::VisemeOpen, amount(mouth_level_)};
  } else {
    state_.layers.mouth = {Expression::Neutral, amount(-mouth_level_)};
  }
}

void FaceReader::read_eyes(const FaceFeatures& f, Expression shut_code) {
  const FaceFeatures& neutral = *selector_.neutral();
  const float left = f.eye_open_left / std::max(neutral.eye_open_left, 1e-3f), right = f.eye_open_right / std::max(neutral.eye_open_right, 1e-3f);
  const float width = f.mouth_width / std::max(neutral.mouth_width, 1e-3f);
  // A blink: both eyes' lids fall together from where they were the last pictures (their median),
  // while the mouth holds (a smile coming narrows the eyes with the mouth widening). dlib's model
  // hardly follows a shut lid (a photo's eyes drawn shut read 0.65-0.85 of their openness), but
  // its gap falls from the eye's own level by more than its jitter (+-0.05 picture to picture),
  // and both eyes' about as far (a wink squeezes the other eye a little too).
  const auto median = [](std::deque<float> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 1.0f : v[v.size() / 2];
  };
  const float drop_left = median(recent_left_) - left, drop_right = median(recent_right_) - right;
  const bool blink = recent_left_.size() >= 4 && std::min(drop_left, drop_right) > kBlinkDrop && drop_left + drop_right > 2.4f * kBlinkDrop &&
                     std::min(drop_left, drop_right) > 0.5f * std::max(drop_left, drop_right) && std::abs(width - median(recent_width_)) < 0.05f;
  for (auto [recent, value] : {std::pair{&recent_left_, left}, std::pair{&recent_right_, right}, std::pair{&recent_width_, width}}) {
    recent->push_back(value);
    if (recent->size() > kRecent) recent->pop_front();
  }
  // Shut for longer (closed eyes, a wink): as the expression's selector reads them, steadied over
  // pictures, the same rules as the single code's.
  const bool left_closed = blink || shut_code == Expression::EyesClosed || shut_code == Expression::WinkLeft;
  const bool right_closed = blink || shut_code == Expression::EyesClosed || shut_code == Expression::WinkRight;
  const auto shown = [](uint8_t was, bool is_closed, float ratio) -> uint8_t {
    if (is_closed) return 0;
    const int open = int(std::lround(std::clamp(ratio, 0.5f, 1.5f) * 100.0f));
    return was == 0 || std::abs(open - int(was)) >= kEyeStep ? uint8_t(open) : was;
  };
  state_.layers.eye_left = shown(state_.layers.eye_left, left_closed, left);
  state_.layers.eye_right = shown(state_.layers.eye_right, right_closed, right);
}

}  // namespace inkwire
