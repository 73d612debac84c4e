#include "server/face/expression_selector.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace inkwire {

namespace {

// Intensity 0-255 from how far `amount` goes towards `full`. The full amounts are about what the
// development faces show for each expression, which is what the templates (255) reproduce.
uint8_t intensity_of(float amount, float full) { return uint8_t(std::lround(std::clamp(amount / full, 0.0f, 1.0f) * 255.0f)); }


// How shut an eye is against the neutral face's, for winks: the lids' landmarks, or where the
// frames were measured the eye's shade when that fell further (dlib's landmarks do not follow a
// shut lid, but a shut eye loses its white and its iris).
float shut_ratio(float lids, float shade, float neutral_shade) {
  return shade > 0.0f && neutral_shade > 0.0f ? std::min(lids, shade / neutral_shade) : lids;
}

}  // namespace

ExpressionState classify(const FaceFeatures& face, const FaceFeatures& neutral, const SelectionThresholds& t) {
  const float eye_left = face.eye_open_left / std::max(neutral.eye_open_left, 1e-3f);
  const float eye_right = face.eye_open_right / std::max(neutral.eye_open_right, 1e-3f);
  const float shut_left = shut_ratio(eye_left, face.eye_shade_left, neutral.eye_shade_left);
  const float shut_right = shut_ratio(eye_right, face.eye_shade_right, neutral.eye_shade_right);
  const float eyes = 0.5f * (eye_left + eye_right);
  const float mouth_open = face.mouth_open - neutral.mouth_open;
  const float widening = face.mouth_width / std::max(neutral.mouth_width, 1e-3f) - 1.0f;
  const float corner_lift = face.corner_lift - neutral.corner_lift;
  const float brow = 0.5f * ((face.brow_raise_left - neutral.brow_raise_left) + (face.brow_raise_right - neutral.brow_raise_right));
  const float brow_tilt = face.brow_inner_raise - neutral.brow_inner_raise;
  const bool surprised = brow > t.brow_raise || eyes > t.eyes_wide;

  // An open mouth decides first: laughing and surprised faces also narrow or widen the eyes. A
  // widened mouth opened a little is a smile showing its teeth (the development subjects' happy
  // photos open it 0.10-0.21), opened further a laugh.
  if (mouth_open > t.mouth_open) {
    const uint8_t open = intensity_of(mouth_open, 0.3f);
    if (widening > t.smile_width && mouth_open > t.laugh_open) return {Expression::Laugh, std::max(open, intensity_of(widening, 0.2f))};
    if (widening > t.smile_width) return {Expression::Smile, std::max(intensity_of(corner_lift, 0.1f), intensity_of(widening, 0.2f))};
    if (surprised) return {Expression::Surprise, std::max(open, intensity_of(brow, 0.1f))};
    if (widening < -t.round_narrowing) return {Expression::VisemeRound, open};
    return {Expression::VisemeOpen, open};
  }
  const bool left_shut = shut_left < shut_right;
  const float shut = left_shut ? shut_left : shut_right, other_open = left_shut ? eye_right : eye_left;
  // A smile narrows both eyes; with the mouth widened, only an eye clearly more shut than the
  // other winks (a smile under a moustache barely opens the mouth and lands here), and with it
  // widened broadly, none does: a dark eye's shade is the first detail a face video loses.
  const bool smiling_squint = widening > t.broad_smile || (widening > t.smile_width && shut > t.wink_asymmetry * other_open);
  if (shut < t.wink_closed && other_open > t.wink_open && !smiling_squint)
    return {left_shut ? Expression::WinkLeft : Expression::WinkRight, intensity_of(1.0f - shut, 0.8f)};
  if (eyes < t.eyes_closed_mean) return {Expression::EyesClosed, intensity_of(1.0f - eyes, 0.8f)};
  if (widening > t.smile_width || corner_lift > t.smile_corner_lift)
    return {Expression::Smile, std::max(intensity_of(corner_lift, 0.1f), intensity_of(widening, 0.2f))};
  // Sad brows rise too, but tilted (inner ends up) and with the mouth corners down.
  if (corner_lift < -t.sad_corner_drop && brow_tilt > t.sad_brow_tilt) return {Expression::Sad, intensity_of(-corner_lift, 0.1f)};
  if (surprised) return {Expression::Surprise, std::max(intensity_of(brow, 0.1f), intensity_of(eyes - 1.0f, 0.2f))};
  if (brow < -t.brow_lower) return {Expression::Frown, intensity_of(-brow, 0.15f)};
  if (mouth_open > t.viseme_wide_open && widening > 0.5f * t.smile_width) return {Expression::VisemeWide, intensity_of(widening, 0.2f)};
  return {Expression::Neutral, 0};
}

void ExpressionSelector::calibrate(const FaceFeatures& neutral) {
  neutral_ = neutral;
  smoothed_.reset();
  state_ = {};
  candidate_ = Expression::Neutral;
  candidate_frames_ = 0;
}

ExpressionState ExpressionSelector::update(const std::optional<FaceFeatures>& features) {
  if (!features) return state_;
  if (!neutral_) {
    calibration_sum_ = calibration_sum_ + *features;
    if (++calibration_count_ >= options_.calibration_frames) calibrate((1.0f / float(calibration_count_)) * calibration_sum_);
    return state_;
  }
  const float a = options_.smoothing;
  smoothed_ = smoothed_ ? a * *features + (1.0f - a) * *smoothed_ : *features;
  const ExpressionState seen = classify(*smoothed_, *neutral_, options_.thresholds);

  // Hysteresis: another expression takes over only after winning hold_frames frames in a row;
  // the intensity of the current one follows in steps.
  if (seen.expression != state_.expression) {
    candidate_frames_ = seen.expression == candidate_ ? candidate_frames_ + 1 : 1;
    candidate_ = seen.expression;
    if (candidate_frames_ >= options_.hold_frames) {
      state_ = seen;
      candidate_frames_ = 0;
    }
  } else {
    candidate_frames_ = 0;
    candidate_ = seen.expression;
    if (std::abs(int(seen.intensity) - int(state_.intensity)) >= options_.intensity_step) state_.intensity = seen.intensity;
  }
  return state_;
}

}  // namespace inkwire
