#include "common/face/face_layers.hpp"

#include <algorithm>
#include <cmath>

namespace inkwire {
namespace {

using E = Expression;

// The mouth's landmarks: the lips and the jaw below the cheekbones, which open with it.
bool in_mouth(int i) { return (i >= 3 && i <= 13) || (i >= face_index::kMouthLeft && i <= face_index::kInnerLipLast); }

// Each eye: its corners and its lids as (upper, lower) pairs, upper 1-2 over lower 5-4.
struct Eye {
  int corner_a, corner_b;
  std::array<std::pair<int, int>, 2> lids;
};
constexpr Eye kLeftEye{36, 39, {{{37, 41}, {38, 40}}}}, kRightEye{42, 45, {{{43, 47}, {44, 46}}}};

bool is_lid(int i) {
  for (const Eye& eye : {kLeftEye, kRightEye})
    for (const auto& [upper, lower] : eye.lids)
      if (i == upper || i == lower) return true;
  return false;
}

// Shut lids meet 80% of the way down from the upper one (as the eyes-closed template closes them:
// the upper lid does most of the moving).
constexpr float kLidsMeet = 0.8f;
// The mean face's lid gap (dlib's examples' hand-placed landmarks, 43 faces), inter-ocular units.
constexpr float kMeanLidGap = 0.0975f;

constexpr float kShut = 75, kStillOpen = 85;  // eye openness (percent) read as shut, and as open beside a shut one

uint8_t percent(float ratio) { return uint8_t(std::lround(std::clamp(ratio, 0.0f, 2.0f) * 100.0f)); }
uint8_t intensity_of(float amount) { return uint8_t(std::lround(std::clamp(amount, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

uint8_t template_eye_openness(const ExpressionTemplates& templates, E e, uint8_t intensity, bool left) {
  const auto& offsets = templates.offsets[size_t(e)];
  if (!offsets) return kEyeOpen;
  float wider = 0;
  for (const auto& [upper, lower] : (left ? kLeftEye : kRightEye).lids) wider += 0.5f * ((*offsets)[size_t(lower)].y - (*offsets)[size_t(upper)].y);
  return percent(1.0f + float(intensity) / 255.0f * wider / kMeanLidGap);
}

FaceLayers layers_of(ExpressionState state, const ExpressionTemplates& templates) {
  FaceLayers out;
  const float shut = float(state.intensity) / 255.0f;
  switch (state.expression) {
    case E::EyesClosed: out.eye_left = out.eye_right = percent(1.0f - shut); break;
    case E::WinkLeft: out.eye_left = percent(1.0f - shut); break;
    case E::WinkRight: out.eye_right = percent(1.0f - shut); break;
    case E::VisemeClosed:
    case E::VisemeOpen:
    case E::VisemeWide:
    case E::VisemeRound: out.mouth = state; break;
    default:
      out.expression = state;
      out.eye_left = template_eye_openness(templates, state.expression, state.intensity, true);
      out.eye_right = template_eye_openness(templates, state.expression, state.intensity, false);
  }
  return out;
}

ExpressionState dominant_expression(const FaceLayers& l) {
  const E mouth = l.mouth.intensity > 0 ? l.mouth.expression : E::Neutral, face = l.expression.intensity > 0 ? l.expression.expression : E::Neutral;
  // An open mouth first, as the single code's selector decides: with a smile it laughs, with raised brows it is surprised.
  if (mouth == E::VisemeOpen || mouth == E::VisemeRound || mouth == E::Laugh || mouth == E::Surprise) {
    if (face == E::Smile || face == E::Laugh) return {E::Laugh, std::max(l.mouth.intensity, l.expression.intensity)};
    if (face == E::Surprise) return {E::Surprise, std::max(l.mouth.intensity, l.expression.intensity)};
    return l.mouth;
  }
  if (face == E::Laugh || face == E::Surprise) return l.expression;
  // An eye a quarter shut or more is shut as the single code's selector counts it (its weakest
  // wink or closed eyes come to 75%), against what the expression itself does to it (a smile
  // narrows the eyes to 70-80%: not shut).
  const float own_left = float(template_eye_openness(shipped_templates(), face, l.expression.intensity, true));
  const float own_right = float(template_eye_openness(shipped_templates(), face, l.expression.intensity, false));
  const float left = float(l.eye_left) * 100.0f / std::max(own_left, 1.0f), right = float(l.eye_right) * 100.0f / std::max(own_right, 1.0f);
  const float shut = std::min(left, right), open = std::max(left, right);
  if (shut <= kShut && open >= kStillOpen) return {left < right ? E::WinkLeft : E::WinkRight, intensity_of(1.0f - shut / 100.0f)};
  const float eyes = 0.5f * (left + right);
  if (eyes <= kShut) return {E::EyesClosed, intensity_of(1.0f - eyes / 100.0f)};
  if (face != E::Neutral) return l.expression;
  if (mouth != E::Neutral) return l.mouth;
  return {};
}

FaceLandmarks apply_layers(const FaceLandmarks& neutral, const ExpressionTemplates& templates, const FaceLayers& layers) {
  const FaceFrame frame = face_frame(neutral);
  const FaceLandmarks face = to_face(neutral, frame);
  static const FaceLandmarks kNone{};
  const auto offsets = [&](E e) -> const FaceLandmarks& { return templates.offsets[size_t(e)] ? *templates.offsets[size_t(e)] : kNone; };
  const FaceLandmarks& expression = offsets(layers.expression.expression);
  const FaceLandmarks& mouth = offsets(layers.mouth.expression);
  const float a = float(layers.expression.intensity) / 255.0f, b = float(layers.mouth.intensity) / 255.0f;
  const E mouth_code = layers.mouth.expression;
  FaceLandmarks moved = face;
  for (int i = 0; i < kFaceLandmarks; ++i) {
    if (is_lid(i)) continue;
    const glm::vec2 own = a * expression[size_t(i)];
    if (!in_mouth(i)) moved[size_t(i)] += own;
    else if (mouth_code == E::Neutral) moved[size_t(i)] += (1.0f - b) * own;
    else if (is_viseme(mouth_code)) moved[size_t(i)] += own + b * mouth[size_t(i)];
    else moved[size_t(i)] += b * mouth[size_t(i)];
  }
  // The lids go with their eye's corners, opened or shut about where they meet.
  for (const auto& [eye, openness] : {std::pair{kLeftEye, layers.eye_left}, std::pair{kRightEye, layers.eye_right}}) {
    const glm::vec2 shift = 0.5f * (moved[size_t(eye.corner_a)] - face[size_t(eye.corner_a)] + moved[size_t(eye.corner_b)] - face[size_t(eye.corner_b)]);
    const float o = float(std::min(openness, kMaxEyeOpenness)) / 100.0f;
    for (const auto& [upper, lower] : eye.lids) {
      const glm::vec2 u = face[size_t(upper)], l = face[size_t(lower)], meet = u + kLidsMeet * (l - u);
      moved[size_t(upper)] = meet + o * (u - meet) + shift;
      moved[size_t(lower)] = meet + o * (l - meet) + shift;
    }
  }
  return to_image(moved, frame);
}

}  // namespace inkwire
