#include "common/face/face_shape.hpp"

#include <glm/geometric.hpp>

#include "common/error.hpp"

namespace inkwire {

namespace {

glm::vec2 eye_centre(const FaceLandmarks& p, int first) { return 0.5f * (p[size_t(first)] + p[size_t(first + 3)]); }
glm::vec2 perpendicular(glm::vec2 axis) { return {-axis.y, axis.x}; }  // x turned a quarter towards y (down)

}  // namespace

glm::vec2 FaceFrame::to_face(glm::vec2 image_point) const {
  const glm::vec2 d = (image_point - origin) / scale;
  return {glm::dot(d, axis), glm::dot(d, perpendicular(axis))};
}

glm::vec2 FaceFrame::to_image(glm::vec2 face_point) const { return origin + offset_to_image(face_point); }

glm::vec2 FaceFrame::offset_to_image(glm::vec2 face_offset) const {
  return scale * (face_offset.x * axis + face_offset.y * perpendicular(axis));
}

FaceFrame face_frame(const FaceLandmarks& landmarks) {
  const glm::vec2 left = eye_centre(landmarks, face_index::kEyeLeftFirst);
  const glm::vec2 right = eye_centre(landmarks, face_index::kEyeRightFirst);
  const float distance = glm::length(right - left);
  if (!(distance > 1e-3f)) throw Error("face landmarks: the eyes coincide");
  return {0.5f * (left + right), (right - left) / distance, distance};
}

FaceLandmarks to_face(const FaceLandmarks& landmarks, const FaceFrame& frame) {
  FaceLandmarks out;
  for (size_t i = 0; i < out.size(); ++i) out[i] = frame.to_face(landmarks[i]);
  return out;
}

FaceLandmarks to_image(const FaceLandmarks& face_points, const FaceFrame& frame) {
  FaceLandmarks out;
  for (size_t i = 0; i < out.size(); ++i) out[i] = frame.to_image(face_points[i]);
  return out;
}

float mean_landmark_error(const FaceLandmarks& found, const FaceLandmarks& reference) {
  const float scale = face_frame(reference).scale;
  float sum = 0;
  for (size_t i = 0; i < found.size(); ++i) sum += glm::length(found[i] - reference[i]);
  return sum / float(found.size()) / scale;
}

}  // namespace inkwire
