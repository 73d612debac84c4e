#pragma once
// Face reconstruction on the client (SPEC F5, F20-F22): one neutral photo of the speaker and its
// 68 landmarks, sent once, are deformed to each received face: its layers (the expression, the
// mouth, each eye's openness: common/face/face_layers.hpp) move the landmarks in the photo's face
// frame, and the head's pose turns them, with the forehead, the hair and half the neck, over a
// depth for each point (common/face/face_depth.hpp): roll in the picture's plane, yaw and pitch
// about the neck, drawn orthographically, the nearest triangles laid first so a turned nose hides
// the cheek behind it. The photo is warped over a triangulation of the landmarks, the anchors
// around the face and the image border (which stays) by the shared warp engine. Successive faces
// are tweened over about 100 ms, layers and pose alike. When the photo's mouth is closed, an
// opening mouth shows what the photo does not have: the inner-lip triangles are then filled with a
// dark mouth-cavity colour instead of stretched lips.
#include <optional>

#include <glm/vec4.hpp>

#include "client/render/tween/image_warper.hpp"
#include "common/face/expression_templates.hpp"
#include "common/face/face_layers.hpp"

namespace inkwire {

class FaceReconstructor {
 public:
  // Throws inkwire::Error when the landmarks are not a face inside the photo.
  FaceReconstructor(const Image& neutral, const FaceLandmarks& landmarks,
                    const ExpressionTemplates& templates = shipped_templates(), double tween_seconds = 0.1);

  // From what is shown at `now`, tween to `state` over tween_seconds.
  void set_face(const FaceState& state, double now);
  // One code (a session-wide speaker, a script): its layers, the head's pose kept.
  void set_expression(ExpressionState state, double now);
  // The one code for what the face is tweening to: the code set, or what its layers say most.
  ExpressionState expression() const { return target_code_; }
  const FaceState& face() const { return target_; }
  // The landmarks drawn at `now` (image pixels): the layers' landmarks turned by the pose.
  FaceLandmarks landmarks_at(double now) const;
  HeadPose pose_at(double now) const;

  // Warps the photo to the face shown at `now` into the warper's target.
  void render(double now);
  Image read() const { return warper_.read(); }  // upright RGBA, opaque where the photo was
  void composite(const glm::vec4& rect) const { warper_.composite(rect); }

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  float tween(double now) const;  // 0 .. 1 along the tween, eased
  FaceLandmarks layered_at(double now) const;  // the layers' landmarks, before the pose
  int width_, height_;
  const ExpressionTemplates& templates_;
  double tween_seconds_;
  FaceLandmarks neutral_;
  FaceFrame frame_;                 // the neutral photo's face frame: the pose turns the head in it
  WarpMesh mesh_points_;            // source (p0) fixed; target (p1) rewritten per frame
  std::vector<int> landmark_of_;    // per mesh point: its landmark, or -1 for anchors and the border
  std::vector<glm::vec3> head_point_;  // per mesh point: its place on the head (face frame, depth)
  std::vector<float> follows_;      // per mesh point: how far it turns with the head
  std::vector<std::array<uint32_t, 3>> triangles_;  // as laid last, nearest first
  gl::Texture atlas_;               // the photo with a strip of mouth-cavity colour below it
  ImageWarper warper_;
  int mesh_ = 0;
  FaceLandmarks from_, to_;         // the layers' landmarks, unposed
  HeadPose from_pose_, to_pose_;
  double start_ = 0;
  FaceState target_;
  ExpressionState target_code_;
};

}  // namespace inkwire
