// What the server reads of a member's face picture after picture (SPEC F20-F22): blinks as blinks,
// a smile's narrowed eyes not as shut ones, the pose with the layers. On synthetic landmarks.
#include <gtest/gtest.h>

#include "server/face/face_reader.hpp"
#include "server/face/layers_stream.hpp"
#include "synthetic_face.hpp"

namespace inkwire {
namespace {

// The eyes' openness each picture shows as the reader reads `faces` one after another.
std::vector<std::pair<int, int>> eyes_read(const std::vector<test::FacePose>& faces) {
  FaceReader reader;
  reader.calibrate(test::synthetic_face({}));
  std::vector<std::pair<int, int>> out;
  for (const test::FacePose& f : faces) {
    const FaceState& s = reader.read(test::synthetic_face(f));
    out.push_back({s.layers.eye_left, s.layers.eye_right});
  }
  return out;
}

// A neutral face's eyes with the jitter dlib's landmarks have (+-0.04 of their openness).
test::FacePose jittered(int k) {
  const float jitter = 0.3f * 0.04f * float((k * 7) % 5 - 2) / 2.0f;
  return {.eye_open_left = 0.3f + jitter, .eye_open_right = 0.3f - jitter};
}

TEST(FaceReaderTest, ABlinkOfTwoPicturesIsReadAsBothEyesShutThenOpen) {
  // dlib's lids follow a shut eye only part way: a blink reads as the gap falling to about 0.65.
  std::vector<test::FacePose> faces;
  for (int k = 0; k < 10; ++k) faces.push_back(jittered(k));
  faces.push_back({.eye_open_left = 0.3f * 0.68f, .eye_open_right = 0.3f * 0.7f});
  faces.push_back({.eye_open_left = 0.3f * 0.72f, .eye_open_right = 0.3f * 0.66f});
  for (int k = 0; k < 6; ++k) faces.push_back(jittered(k));
  const auto eyes = eyes_read(faces);
  for (int k = 0; k < 10; ++k) EXPECT_EQ(eyes[size_t(k)], std::pair(100, 100)) << "picture " << k << ": jitter is not a blink";
  EXPECT_EQ(eyes[10], std::pair(0, 0));
  EXPECT_EQ(eyes[11], std::pair(0, 0));
  EXPECT_GE(eyes[12].first, 90) << "open again";
  EXPECT_GE(eyes[12].second, 90);
}

TEST(FaceReaderTest, ASmileNarrowingTheEyesIsNoBlinkAndOneEyeFallingIsNone) {
  std::vector<test::FacePose> faces;
  for (int k = 0; k < 10; ++k) faces.push_back(jittered(k));
  // The mouth widens as the eyes narrow to 0.7: a smile coming, drawn narrowed, not shut.
  for (int k = 0; k < 3; ++k) faces.push_back({.eye_open_left = 0.21f, .eye_open_right = 0.21f, .mouth_widen = 0.06f, .corner_lift = 0.06f});
  const auto eyes = eyes_read(faces);
  EXPECT_GT(eyes[10].first, 60);
  EXPECT_LT(eyes[10].first, 80);
  // One eye's gap falling alone for a picture is no blink (the selector reads longer winks).
  faces.resize(10);
  faces.push_back({.eye_open_left = 0.18f, .eye_open_right = 0.3f});
  EXPECT_GT(eyes_read(faces)[10].second, 90);
}

TEST(FaceReaderTest, AStillFaceSendsKeepAlivesOnlyAndATurnedOneItsPose) {
  FaceReader reader;
  const FaceLandmarks neutral = test::synthetic_face({});
  reader.calibrate(neutral);
  LayersStream stream(2.0);
  int sent = 0;
  for (int k = 0; k < 45; ++k)  // three seconds at 15 a second, the lids jittering
    sent += stream.next(reader.read(test::synthetic_face(jittered(k))), k / 15.0, 1, uint32_t(k * 66)).has_value();
  EXPECT_EQ(sent, 2) << "the first and one keep-alive";
  // The head rolled 10 degrees: sent, with the pose.
  const auto turned = stream.next(reader.read(test::synthetic_face({}, {160, 120}, 60, 0.1745f)), 3.1, 1, 3100);
  ASSERT_TRUE(turned);
  EXPECT_EQ(turned->roll, 10);
}

}  // namespace
}  // namespace inkwire
