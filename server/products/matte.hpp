#pragma once
// Mattes for photos taken against a plain studio background (SPEC T14): where the object is, as
// an alpha channel, so views between samples can show one outline. The background's colour is
// read off the photo's border; a border that is not one plain colour cannot be keyed.
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "common/image.hpp"

namespace inkwire {

struct MatteResult {
  bool keyed = false;
  std::string reason;        // why not, when not keyed
  double object_fraction = 0;  // share of the image the object covers
  double floor_fraction = 0;   // share of the image its floor layer (shadow, reflection) covers
  glm::vec3 backdrop{0.0f};    // the backdrop's colour (RGB, 0-255), when keyed
};

// How many pixels wide the outer 2% of a picture is (at least 2): the band taken as backdrop.
int border_band(int width, int height);

// The backdrop's colour: the per-channel median of the photo's outer 2% (RGB, 0-255).
glm::vec3 backdrop_colour(const Image& photo);

// Sets `photo`'s alpha to the object's matte (255 inside, 0 on the background, a pixel of soft
// edge between). Holes enclosed by the object are filled: a matte says where the object's
// outline is, and a hole the colour of the backdrop inside it is far more often paint than air.
// The floor under the object (SPEC T16) is not object: a soft shadow is taken out of the matte,
// and where the matte is 0 the colours become the floor layer as it would look on a white
// backdrop (the photo divided by the backdrop's colour where it differs from the backdrop next
// to the object, white everywhere else). Clients lay that layer under the object's outline.
// Leaves `photo` untouched and says why when the border is not plain or nothing stands out.
MatteResult key_plain_background(Image& photo);

// Keys `larger`, the same photo at a larger size (a zoom level, SPEC T18), as `keyed` was keyed
// against `backdrop`: the matte and the floor layer scaled up (bilinear, as clients scale the
// matte they lay the level over), not found again.
void key_like(Image& larger, const Image& keyed, const glm::vec3& backdrop);

// A keyed photo as it is stored and shown: the object laid on white by its matte, its floor layer
// (the colours where the matte is 0) as it is. Opaque.
Image laid_on_white(const Image& keyed);

}  // namespace inkwire
