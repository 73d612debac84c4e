// Expression features, selection and templates on drawn (synthetic) landmark sets: no photos,
// no landmark model.
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/face/expression_templates.hpp"
#include "server/face/expression_selector.hpp"
#include "synthetic_face.hpp"

namespace inkwire {
namespace {

using test::FacePose;
using test::synthetic_face;

TEST(FaceFeatures, DoNotDependOnPositionScaleOrRoll) {
  const FacePose pose{.eye_open_left = 0.2f, .brow_raise = 0.05f, .mouth_open = 0.2f, .corner_lift = 0.04f};
  const FaceFeatures a = measure_features(synthetic_face(pose));
  const FaceFeatures b = measure_features(synthetic_face(pose, {400, 300}, 170, 0.4f));
  EXPECT_NEAR(a.eye_open_left, 0.2f, 1e-4f);
  EXPECT_NEAR(a.eye_open_right, 0.3f, 1e-4f);
  EXPECT_NEAR(a.mouth_open, 0.2f, 1e-4f);
  for (auto [x, y] : {std::pair{a.eye_open_left, b.eye_open_left}, {a.brow_raise_left, b.brow_raise_left}, {a.mouth_open, b.mouth_open},
                      {a.mouth_width, b.mouth_width}, {a.corner_lift, b.corner_lift}, {a.jaw_drop, b.jaw_drop}})
    EXPECT_NEAR(x, y, 1e-4f);
}

TEST(FaceFrame, RoundTripsAndMeasuresTheEyes) {
  const FaceLandmarks face = synthetic_face({}, {200, 150}, 80, 0.3f);
  const FaceFrame frame = face_frame(face);
  EXPECT_NEAR(frame.scale, 80.0f, 1e-3f);
  for (const glm::vec2& p : face) {
    const glm::vec2 back = frame.to_image(frame.to_face(p));
    EXPECT_NEAR(back.x, p.x, 1e-3f);
    EXPECT_NEAR(back.y, p.y, 1e-3f);
  }
  FaceLandmarks collapsed{};
  EXPECT_THROW(face_frame(collapsed), Error);
}

struct Case {
  const char* what;
  FacePose pose;
  Expression expected;
};

TEST(ExpressionSelection, TableOfSyntheticFaces) {
  const FaceFeatures neutral = measure_features(synthetic_face({}));
  const Case cases[] = {
      {"neutral", {}, Expression::Neutral},
      {"tiny changes", {.eye_open_left = 0.28f, .brow_raise = 0.02f, .mouth_open = 0.03f}, Expression::Neutral},
      {"smile: corners up and out", {.mouth_widen = 0.05f, .corner_lift = 0.07f}, Expression::Smile},
      {"laugh: open and wide", {.mouth_open = 0.25f, .mouth_widen = 0.08f, .corner_lift = 0.05f}, Expression::Laugh},
      {"surprise: brows up, mouth open", {.brow_raise = 0.12f, .mouth_open = 0.3f}, Expression::Surprise},
      {"surprise: brows and eyes only", {.eye_open_left = 0.36f, .eye_open_right = 0.36f, .brow_raise = 0.1f}, Expression::Surprise},
      {"frown: brows down", {.brow_raise = -0.09f}, Expression::Frown},
      {"sad: corners down, brows tilted", {.brow_inner_raise = 0.08f, .corner_lift = -0.06f}, Expression::Sad},
      {"eyes closed", {.eye_open_left = 0.05f, .eye_open_right = 0.05f}, Expression::EyesClosed},
      {"drowsy eyes count as closed", {.eye_open_left = 0.2f, .eye_open_right = 0.2f}, Expression::EyesClosed},
      {"wink left", {.eye_open_left = 0.05f, .eye_open_right = 0.3f}, Expression::WinkLeft},
      {"wink right", {.eye_open_left = 0.3f, .eye_open_right = 0.04f}, Expression::WinkRight},
      {"viseme open: jaw down", {.mouth_open = 0.2f, .jaw_drop = 0.1f}, Expression::VisemeOpen},
      {"viseme round: open and narrow", {.mouth_open = 0.2f, .mouth_widen = -0.08f}, Expression::VisemeRound},
      {"viseme wide: spread, slightly open", {.mouth_open = 0.06f, .mouth_widen = 0.02f}, Expression::VisemeWide},
  };
  for (const Case& c : cases) {
    const ExpressionState s = classify(measure_features(synthetic_face(c.pose)), neutral);
    EXPECT_EQ(name_of(s.expression), std::string(name_of(c.expected))) << c.what;
    if (c.expected != Expression::Neutral) {
      EXPECT_GT(s.intensity, 0) << c.what;
    }
  }
}

TEST(ExpressionSelection, IntensityGrowsWithTheExpression) {
  const FaceFeatures neutral = measure_features(synthetic_face({}));
  int last = -1;
  for (float open : {0.15f, 0.2f, 0.25f, 0.3f}) {
    const ExpressionState s = classify(measure_features(synthetic_face({.brow_raise = 0.065f, .mouth_open = open})), neutral);
    ASSERT_EQ(s.expression, Expression::Surprise);
    EXPECT_GT(int(s.intensity), last);
    last = s.intensity;
  }
}

TEST(ExpressionSelector, CalibratesOnTheFirstFramesThenHoldsAgainstFlicker) {
  // A speaker whose neutral face has narrow eyes: relative to the default that would read as
  // drowsy, relative to the speaker it is neutral.
  const FacePose speaker{.eye_open_left = 0.22f, .eye_open_right = 0.22f};
  ExpressionSelector selector({.calibration_frames = 10, .smoothing = 1.0f, .hold_frames = 3, .intensity_step = 16, .thresholds = {}});
  for (int i = 0; i < 10; ++i) EXPECT_EQ(selector.update(measure_features(synthetic_face(speaker))).expression, Expression::Neutral);
  ASSERT_TRUE(selector.calibrated());
  EXPECT_EQ(selector.update(measure_features(synthetic_face(speaker))).expression, Expression::Neutral);

  FacePose smiling = speaker;
  smiling.mouth_widen = 0.05f, smiling.corner_lift = 0.07f;
  // One smiling frame between neutral ones is a flicker: no change.
  EXPECT_EQ(selector.update(measure_features(synthetic_face(smiling))).expression, Expression::Neutral);
  EXPECT_EQ(selector.update(measure_features(synthetic_face(speaker))).expression, Expression::Neutral);
  // Three in a row take over; a missing face keeps the state.
  selector.update(measure_features(synthetic_face(smiling)));
  selector.update(measure_features(synthetic_face(smiling)));
  EXPECT_EQ(selector.update(measure_features(synthetic_face(smiling))).expression, Expression::Smile);
  EXPECT_EQ(selector.update(std::nullopt).expression, Expression::Smile);
}

TEST(ExpressionTemplates, ShippedSetIsCompleteAndEachTemplateReadsAsItsExpression) {
  const ExpressionTemplates& t = shipped_templates();
  const FaceLandmarks neutral = synthetic_face({}, {320, 240}, 90, 0.1f);
  const FaceFeatures neutral_features = measure_features(neutral);
  for (int e = 1; e < kExpressionCount; ++e) {
    const Expression expression = Expression(e);
    ASSERT_TRUE(t.offsets[size_t(e)].has_value()) << name_of(expression);
    EXPECT_FALSE(t.made_each[size_t(e)].empty()) << name_of(expression);
    // Pressed lips and the mean sad face are too subtle to select from a still (as on the photos).
    if (expression == Expression::VisemeClosed || expression == Expression::Sad) continue;
    const FaceLandmarks moved = apply_expression(neutral, t, {expression, 255});
    const ExpressionState seen = classify(measure_features(moved), neutral_features);
    if (expression == Expression::Smile) {  // the measured smile shows teeth: a laugh is as right
      EXPECT_TRUE(seen.expression == Expression::Smile || seen.expression == Expression::Laugh) << name_of(seen.expression);
    } else {
      EXPECT_EQ(std::string(name_of(seen.expression)), name_of(expression));
    }
  }
  // Intensity 0 is the neutral face itself.
  EXPECT_EQ(apply_expression(neutral, t, {Expression::Surprise, 0}), neutral);
}

TEST(ExpressionTemplates, MalformedFilesAreRejectedWithAReason) {
  const std::string head = R"({"format": "inkwire-expression-templates", "version": 1, "templates": )";
  EXPECT_THROW(parse_templates("not json"), Error);
  EXPECT_THROW(parse_templates(R"({"format": "other", "version": 1, "templates": {}})"), Error);
  EXPECT_THROW(parse_templates(head + R"({"grin": {"offsets": []}}})"), Error);
  EXPECT_THROW(parse_templates(head + R"({"smile": {"offsets": [[0, 0]]}}})"), Error);
  std::string points = "[";
  for (int i = 0; i < 68; ++i) points += std::string(i ? "," : "") + (i == 5 ? "[0, 1e9]" : "[0, 0]");
  points += "]";
  EXPECT_THROW(parse_templates(head + R"({"smile": {"offsets": )" + points + "}}}"), Error);
  // A template written and read back is the same.
  const ExpressionTemplates again = parse_templates(templates_to_json(shipped_templates()));
  for (int e = 0; e < kExpressionCount; ++e)
    for (size_t i = 0; i < kFaceLandmarks; ++i) {
      EXPECT_NEAR((*again.offsets[size_t(e)])[i].x, (*shipped_templates().offsets[size_t(e)])[i].x, 1e-4f);
      EXPECT_NEAR((*again.offsets[size_t(e)])[i].y, (*shipped_templates().offsets[size_t(e)])[i].y, 1e-4f);
    }
}

// A smile that shows its teeth (the development subjects' happy photos open the lips 0.10-0.21
// inter-ocular units) is a smile; only a mouth opened further laughs.
// A neutral face's features: eyes 0.3 open, the mouth 1 wide, the rest 0.
FaceFeatures plain_neutral() {
  FaceFeatures neutral;
  neutral.eye_open_left = neutral.eye_open_right = 0.3f;
  neutral.mouth_width = 1.0f;
  return neutral;
}

TEST(ExpressionSelection, ASmileShowingTeethIsASmileAndAWideOpenOneALaugh) {
  const FaceFeatures neutral = plain_neutral();
  FaceFeatures smiling = neutral;
  smiling.mouth_width = 1.2f;
  for (const float open : {0.12f, 0.18f}) {
    smiling.mouth_open = neutral.mouth_open + open;
    EXPECT_EQ(classify(smiling, neutral).expression, Expression::Smile) << "lips apart by " << open;
  }
  smiling.mouth_open = neutral.mouth_open + 0.3f;
  EXPECT_EQ(classify(smiling, neutral).expression, Expression::Laugh);
}

TEST(ExpressionSelection, ASmileThatNarrowsBothEyesOrABroadSmileIsNoWinkButOneShutEyeStillWinks) {
  const FaceFeatures neutral = plain_neutral();
  // Yale subject 15's happy photo: eyes at 0.74 and 0.83 of neutral, the mouth 24% wider, closed.
  FaceFeatures smiling = neutral;
  smiling.mouth_width = 1.24f;
  smiling.eye_open_left = 0.74f * 0.3f;
  smiling.eye_open_right = 0.83f * 0.3f;
  EXPECT_EQ(classify(smiling, neutral).expression, Expression::Smile);
  // A mouth widened as a wink may widen it (the development faces' winks: up to 16%) with one eye
  // clearly shut is a wink.
  FaceFeatures winking = smiling;
  winking.mouth_width = 1.12f;
  winking.eye_open_left = 0.5f * 0.3f;
  winking.eye_open_right = 0.9f * 0.3f;
  EXPECT_EQ(classify(winking, neutral).expression, Expression::WinkLeft);
  // A broad smile is a smile whatever one eye does: Yale subject 13's happy photo through the face
  // video, the mouth 40% wider, the right eye's lids at 0.9 of neutral and its shade at 0.68
  // (a dark eye loses its detail to the codec first).
  FaceFeatures shaded = neutral;
  shaded.eye_shade_left = 29.0f, shaded.eye_shade_right = 19.0f;
  FaceFeatures broad = shaded;
  broad.mouth_width = 1.4f;
  broad.eye_open_right = 0.9f * 0.3f;
  broad.eye_shade_left = 0.85f * shaded.eye_shade_left;
  broad.eye_shade_right = 0.68f * shaded.eye_shade_right;
  EXPECT_EQ(classify(broad, shaded).expression, Expression::Smile);
  // Without the widened mouth the narrower eye alone decides, as before.
  FaceFeatures squint = neutral;
  squint.eye_open_left = 0.74f * 0.3f;
  squint.eye_open_right = 0.83f * 0.3f;
  EXPECT_EQ(classify(squint, neutral).expression, Expression::WinkLeft);
}

}  // namespace
}  // namespace inkwire
