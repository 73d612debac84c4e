#pragma once
// Face reconstruction on the client (SPEC F5): one neutral photo of the speaker and its 68
// landmarks, sent once, are deformed to each received expression code. The landmarks move by
// the expression's template (scaled by its intensity, in the photo's face frame); the photo is
// warped over a triangulation of the landmarks, a fixed ring of anchors around the face and the
// image border (so the face border does not tear and the background stays put) by the shared
// warp engine. Successive expressions are tweened over about 100 ms. When the photo's mouth is
// closed, an opening mouth shows what the photo does not have: the inner-lip triangles are then
// filled with a dark mouth-cavity colour instead of stretched lips.
#include <optional>

#include <glm/vec4.hpp>

#include "client/render/tween/image_warper.hpp"
#include "common/face/expression_templates.hpp"

namespace inkwire {

class FaceReconstructor {
 public:
  // Throws inkwire::Error when the landmarks are not a face inside the photo.
  FaceReconstructor(const Image& neutral, const FaceLandmarks& landmarks,
                    const ExpressionTemplates& templates = shipped_templates(), double tween_seconds = 0.1);

  // From what is shown at `now`, tween to `state` over tween_seconds.
  void set_expression(ExpressionState state, double now);
  ExpressionState expression() const { return target_state_; }
  // The landmarks shown at `now` (image pixels).
  FaceLandmarks landmarks_at(double now) const;

  // Warps the photo to the face shown at `now` into the warper's target.
  void render(double now);
  Image read() const { return warper_.read(); }  // upright RGBA, opaque where the photo was
  void composite(const glm::vec4& rect) const { warper_.composite(rect); }

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  const ExpressionTemplates& templates_;
  double tween_seconds_;
  FaceLandmarks neutral_;
  WarpMesh mesh_points_;            // source (p0) fixed; target (p1) rewritten per frame
  std::vector<int> landmark_of_;    // per mesh point: its landmark, or -1 for fixed anchors
  gl::Texture atlas_;               // the photo with a strip of mouth-cavity colour below it
  ImageWarper warper_;
  int mesh_ = 0;
  FaceLandmarks from_, to_;
  double start_ = 0;
  ExpressionState target_state_;
};

}  // namespace inkwire
