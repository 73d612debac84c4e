// A face in layers (SPEC F21-F22): the expression, the mouth and each eye on their own, mixed; one
// code as layers and back; a member-face of protocol version 7 as layers and back.
#include <gtest/gtest.h>

#include "common/face/face_layers.hpp"
#include "protocol/face_versions.hpp"
#include "server/face/face_features.hpp"
#include "synthetic_face.hpp"

namespace inkwire {
namespace {

using E = Expression;

FaceFeatures features(const FaceLayers& layers) { return measure_features(apply_layers(test::synthetic_face({}), shipped_templates(), layers)); }

TEST(FaceLayersTest, NeutralLayersAreTheNeutralFace) {
  const FaceLandmarks neutral = test::synthetic_face({}, {200, 150}, 70, 0.2f);
  const FaceLandmarks shown = apply_layers(neutral, shipped_templates(), {});
  for (size_t i = 0; i < shown.size(); ++i) EXPECT_NEAR(glm::distance(shown[i], neutral[i]), 0.0f, 1e-3f) << i;
}

TEST(FaceLayersTest, EachEyeOpensAndShutsOnItsOwn) {
  const FaceFeatures neutral = features({});
  const FaceFeatures blink = features({.eye_left = 0, .eye_right = 0});
  EXPECT_LT(blink.eye_open_left, 0.02f);
  EXPECT_LT(blink.eye_open_right, 0.02f);
  const FaceFeatures wink = features({.eye_left = 0, .eye_right = kEyeOpen});
  EXPECT_LT(wink.eye_open_left, 0.02f);
  EXPECT_NEAR(wink.eye_open_right, neutral.eye_open_right, 1e-4f);
  const FaceFeatures half = features({.eye_left = 50, .eye_right = 150});
  EXPECT_NEAR(half.eye_open_left / neutral.eye_open_left, 0.5f, 0.02f);
  EXPECT_NEAR(half.eye_open_right / neutral.eye_open_right, 1.5f, 0.02f);
  // The rest of the face does not move with the eyes.
  EXPECT_NEAR(blink.mouth_open, neutral.mouth_open, 1e-4f);
  EXPECT_NEAR(blink.brow_raise_left, neutral.brow_raise_left, 1e-4f);
}

TEST(FaceLayersTest, ASmileWhileTalkingShowsBoth) {
  const FaceFeatures neutral = features({});
  const FaceFeatures smile = features({.expression = {E::Smile, 255}});
  const FaceFeatures talking = features({.mouth = {E::VisemeOpen, 255}});
  const FaceFeatures both = features({.expression = {E::Smile, 255}, .mouth = {E::VisemeOpen, 255}});
  // The mouth opens as far as talking opens it (the smile's own opening over it) ...
  EXPECT_GT(both.mouth_open, neutral.mouth_open + 0.8f * (talking.mouth_open - neutral.mouth_open));
  // ... its corners widened and lifted more than talking alone, and the face (the jaw line's
  // cheeks) as the smile has it.
  EXPECT_GT(both.mouth_width, talking.mouth_width + 0.5f * (smile.mouth_width - neutral.mouth_width));
  EXPECT_GT(both.corner_lift, talking.corner_lift + 0.5f * (smile.corner_lift - neutral.corner_lift));
  const FaceLandmarks cheeks_smiling = apply_layers(test::synthetic_face({}), shipped_templates(), {.expression = {E::Smile, 255}});
  const FaceLandmarks cheeks_both = apply_layers(test::synthetic_face({}), shipped_templates(), {.expression = {E::Smile, 255}, .mouth = {E::VisemeOpen, 255}});
  for (int i : {0, 1, 15, 16, 17, 21, 26, 31, 35}) EXPECT_NEAR(glm::distance(cheeks_smiling[size_t(i)], cheeks_both[size_t(i)]), 0.0f, 1e-4f) << i;
  // An expression's mouth in the mouth layer replaces the expression's own.
  const FaceFeatures surprised_mouth = features({.expression = {E::Smile, 255}, .mouth = {E::Surprise, 255}});
  const FaceFeatures surprise = features({.expression = {E::Surprise, 255}});
  EXPECT_NEAR(surprised_mouth.mouth_open, surprise.mouth_open, 1e-4f);
}

TEST(FaceLayersTest, OneCodeAsLayersSaysTheSameCode) {
  // At full intensity, and at the weakest the selector sends of each (a wink or shut eyes from
  // 64 up: their eyes 75% open).
  for (const int intensity : {255, 64})
  for (int code = 0; code < kExpressionCount; ++code) {
    const ExpressionState state{E(code), uint8_t(intensity)};
    const FaceLayers layers = layers_of(state);
    EXPECT_TRUE(expression_layer_takes(layers.expression.expression)) << name_of(E(code));
    EXPECT_TRUE(mouth_layer_takes(layers.mouth.expression)) << name_of(E(code));
    if (code == 0) continue;
    EXPECT_EQ(dominant_expression(layers).expression, state.expression) << name_of(E(code)) << " at " << intensity;
  }
  EXPECT_EQ(layers_of({E::WinkRight, 255}).eye_right, 0);
  EXPECT_EQ(layers_of({E::WinkRight, 255}).eye_left, kEyeOpen);
  EXPECT_EQ(layers_of({E::EyesClosed, 255}).eye_left, 0);
  EXPECT_LT(layers_of({E::Smile, 255}).eye_left, kEyeOpen);      // a smile narrows the eyes
  EXPECT_GT(layers_of({E::Surprise, 255}).eye_left, kEyeOpen);   // a surprise widens them
}

TEST(FaceLayersTest, TheCodeOfLayersPutsAnOpenMouthFirstThenShutEyes) {
  EXPECT_EQ(dominant_expression({.expression = {E::Smile, 200}, .mouth = {E::VisemeOpen, 150}}).expression, E::Laugh);
  EXPECT_EQ(dominant_expression({.expression = {E::Smile, 200}, .mouth = {E::VisemeClosed, 150}}).expression, E::Smile);
  EXPECT_EQ(dominant_expression({.expression = {E::Smile, 200}, .eye_left = 5, .eye_right = 5}).expression, E::EyesClosed);
  EXPECT_EQ(dominant_expression({.eye_left = 100, .eye_right = 10}).expression, E::WinkRight);
  EXPECT_EQ(dominant_expression({.mouth = {E::VisemeWide, 150}}).expression, E::VisemeWide);
  EXPECT_EQ(dominant_expression({}).expression, E::Neutral);
}

TEST(FaceLayersTest, AMemberFaceOfVersion7ReadsAsLayersAndLayersAreSentToSuchAPeerAsOneCode) {
  using namespace protocol;
  const MemberLayers layers{.member = 4, .time_ms = 900, .yaw = 20, .pitch = -5, .roll = 12, .expression = {E::Smile, 200},
                            .mouth = {E::VisemeOpen, 180}, .source = FaceSource::Camera};
  const MemberFace legacy = member_face_of(layers);
  EXPECT_EQ(legacy.member, 4);
  EXPECT_EQ(legacy.time_ms, 900u);
  EXPECT_EQ(legacy.expression.code, uint8_t(E::Laugh));
  EXPECT_EQ(legacy.yaw, 20);
  EXPECT_EQ(legacy.roll, 12);
  EXPECT_EQ(legacy.source, FaceSource::Camera);
  const MemberLayers read = member_layers_of({.member = 4, .time_ms = 900, .expression = {.code = uint8_t(E::WinkLeft), .intensity = 255}, .yaw = 120});
  EXPECT_EQ(read.eye_left, 0);
  EXPECT_EQ(read.yaw, kMaxPoseDegrees);  // what version 7 could say past the range, clamped
  EXPECT_EQ(member_layers_of({.expression = {.code = 200, .intensity = 255}}).expression.expression, E::Neutral);  // a code it did not know
  const FaceState state = face_state_of(layers);
  EXPECT_EQ(state.pose.yaw, 20.0f);
  EXPECT_EQ(state.layers.mouth.expression, E::VisemeOpen);
}

}  // namespace
}  // namespace inkwire
