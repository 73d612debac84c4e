// Head pose (SPEC F20): the pose a face is drawn with and the pose read back from its landmarks.
#include <gtest/gtest.h>

#include "common/face/face_depth.hpp"
#include "common/face/head_pose.hpp"
#include "server/face/head_pose.hpp"
#include "synthetic_face.hpp"

namespace inkwire {
namespace {

// A face's landmarks turned by `pose` over the generic depth, as the receiver turns them.
FaceLandmarks posed(const FaceLandmarks& neutral, const HeadPose& pose) {
  const FaceFrame frame = face_frame(neutral);
  const FaceLandmarks face = to_face(neutral, frame);
  const auto depth = landmark_depths(face);
  const glm::mat3 rotation = rotation_of(pose);
  FaceLandmarks out;
  for (size_t i = 0; i < out.size(); ++i) out[i] = frame.to_image(glm::vec2(turned(glm::vec3(face[i], depth[i]), rotation)));
  return out;
}

TEST(FacePoseTest, RotationsTurnTheWayTheWireSays) {
  const glm::vec3 nose{0, 0.6f, 0.67f};
  EXPECT_GT(turned(nose, rotation_of({.yaw = 20})).x, nose.x + 0.3f);     // yaw: towards the image's right
  EXPECT_LT(turned(nose, rotation_of({.pitch = 20})).y, nose.y - 0.3f);   // pitch: up (y is down)
  const glm::vec3 right_eye{0.5f, 0, 0};
  EXPECT_GT(turned(right_eye, rotation_of({.roll = 20})).y, right_eye.y + 0.1f);  // roll: clockwise on screen
  // The pivot stays put whatever the pose.
  const glm::vec3 pivot = turned(kNeckPivot, rotation_of({.yaw = 33, .pitch = -12, .roll = 50}));
  EXPECT_NEAR(glm::length(pivot - kNeckPivot), 0.0f, 1e-5f);
}

TEST(FacePoseTest, TheJawLineCurvesBackToTheEars) {
  EXPECT_NEAR(contour_depth(0), 0.22f, 1e-6f);
  EXPECT_LT(contour_depth(1.2f), -0.9f);
  EXPECT_EQ(contour_depth(1.2f), contour_depth(-1.2f));
  FaceLandmarks wide = to_face(test::synthetic_face({}), face_frame(test::synthetic_face({})));
  const auto depth = landmark_depths(wide);
  EXPECT_LT(depth[0], depth[4]);
  EXPECT_LT(depth[4], depth[8]);
  EXPECT_GT(depth[30], depth[33]);  // the nose's tip stands out beyond its base
  EXPECT_GT(depth[33], depth[39]);
}

TEST(FacePoseTest, APoseDrawnIsThePoseReadBack) {
  const FaceLandmarks neutral = test::synthetic_face({}, {320, 240}, 80, 0.05f);  // the photo's own head a little tilted
  const HeadPose still = head_pose(neutral, neutral);
  EXPECT_NEAR(still.yaw, 0, 0.3f);
  EXPECT_NEAR(still.pitch, 0, 0.3f);
  EXPECT_NEAR(still.roll, 0, 0.3f);
  for (const HeadPose pose : {HeadPose{.yaw = 30}, HeadPose{.yaw = -25}, HeadPose{.pitch = 20}, HeadPose{.pitch = -20}, HeadPose{.roll = 20},
                              HeadPose{.roll = -35}, HeadPose{.yaw = 28, .pitch = -15, .roll = 12}, HeadPose{.yaw = -40, .pitch = 18, .roll = -8}}) {
    const HeadPose read = head_pose(posed(neutral, pose), neutral);
    SCOPED_TRACE(testing::Message() << "drawn " << pose.yaw << ", " << pose.pitch << ", " << pose.roll);
    EXPECT_NEAR(read.yaw, pose.yaw, 0.5f);
    EXPECT_NEAR(read.pitch, pose.pitch, 0.5f);
    EXPECT_NEAR(read.roll, pose.roll, 0.5f);
  }
}

TEST(FacePoseTest, ThePoseIsReadWhereverTheFaceIsAndHoweverLarge) {
  const FaceLandmarks neutral = test::synthetic_face({}, {320, 240}, 80);
  FaceLandmarks moved = posed(neutral, {.yaw = 15, .roll = 10});
  for (glm::vec2& p : moved) p = glm::vec2(100, 50) + 0.5f * p;  // elsewhere in the frame, half the size
  const HeadPose read = head_pose(moved, neutral);
  EXPECT_NEAR(read.yaw, 15, 0.5f);
  EXPECT_NEAR(read.roll, 10, 0.5f);
}

TEST(FacePoseTest, ExpressionsDoNotReadAsAHeadTurning) {
  // An open mouth, a smile and raised brows move none of the points the pose is read from.
  const FaceLandmarks neutral = test::synthetic_face({});
  for (const test::FacePose face : {test::FacePose{.mouth_open = 0.3f, .jaw_drop = 0.2f}, test::FacePose{.mouth_widen = 0.1f, .corner_lift = 0.1f},
                                    test::FacePose{.eye_open_left = 0.05f, .eye_open_right = 0.05f, .brow_raise = 0.12f}}) {
    const HeadPose read = head_pose(test::synthetic_face(face), neutral);
    EXPECT_LT(std::abs(read.yaw) + std::abs(read.pitch) + std::abs(read.roll), 2.0f);
  }
}

}  // namespace
}  // namespace inkwire
