#pragma once
// A call member's neutral photo drawn as a cartoonist draws a face (SPEC C1's look on a picture
// instead of a mesh, SPEC F5's face "rendered in an NPR style"): the person cut from the wall
// (common/face/person_matte.hpp) and laid on the style's ground; tones smoothed by an
// edge-preserving filter and laid in three bands of the person's own light (light, mid, shadow:
// a band is never darker than a dark grey, so eye sockets are not blots), each band's regions
// cleaned of islands; the face's features inked along their landmarks as pen strokes that swell
// and taper (brows, lids, the nose's base, the lips, the jaw over the neck) and the irises filled; the person's outline
// inked; and, inside the person but off the face, the photo's strong edges (hair, ears, collar).
// Drawn once per photo: the warp then moves the face with its ink, as a drawn face moves.
//
// Used by render/face/conference_view.cpp, natively and in the browser's module alike, so it
// needs nothing the module lacks (no OpenCV).
#include <glm/vec3.hpp>

#include "common/face/face_shape.hpp"
#include "common/face/person_matte.hpp"
#include "common/image.hpp"

namespace inkwire {

// In place; alpha is kept. Nothing happens to a photo smaller than 8x8 or of another size than
// the matte.
void comic_face(Image& photo, const FaceLandmarks& landmarks, const PersonMatte& matte, glm::u8vec3 ground);

}  // namespace inkwire
