#pragma once
// The person in a neutral photo (SPEC F5: the face "rendered in an NPR style"): face, hair, neck and shoulders apart from the wall
// behind them, so that a drawn face lays its person on the style's ground instead of inking and
// painting the room. Found as GrabCut (Rother et al. 2004) finds a foreground, with the landmarks
// in place of the user's rectangle: the face's hull is surely the person; what lies far from the
// head and the shoulders the landmarks imply is surely not; between them, each pixel goes to
// whichever colour model (the person's, the wall's, re-estimated a few times) explains it better,
// weighed by how near it is to the head, and smoothed so that the cut follows regions, not grain.
//
// Plain C++ on purpose: the browser's module cuts its call faces with this same code (SPEC F16)
// and has no OpenCV. Only +-*/ on floats and integer counts, so both cut alike bit for bit.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "common/face/face_shape.hpp"
#include "common/image.hpp"

namespace inkwire {

struct PersonMatte {
  int width = 0, height = 0;
  std::vector<uint8_t> alpha;  // 255 the person, 0 the wall, feathered over about a pixel between
  uint8_t at(int x, int y) const { return alpha[size_t(y) * size_t(width) + size_t(x)]; }
};

// The photo's own size. Throws inkwire::Error when the landmarks are not a face (coincident eyes).
PersonMatte person_matte(const Image& photo, const FaceLandmarks& landmarks);

// `image` (the same size as the matte) with everything but the person faded into `ground`, as
// the matte says; alpha is kept.
void lay_on_ground(Image& image, const PersonMatte& matte, glm::u8vec3 ground);

}  // namespace inkwire
