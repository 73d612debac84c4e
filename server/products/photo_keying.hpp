#pragma once
// The pipeline's keying stage, after the turn (turn_angles.hpp): every photo of a product keyed
// against its plain backdrop (matte.hpp), or none. A product whose samples disagree on having an
// outline would show one only some of the way round.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "server/products/photo_folder.hpp"

namespace inkwire {

struct KeyedPhotos {
  bool matted = false;               // every photo keyed (alpha is its matte); false: all shown whole
  std::vector<glm::vec3> backdrops;  // when matted, per photo: its backdrop's colour (RGB, 0-255)
};

// `matte`: "auto" keys a plain backdrop when every photo has one and says why not when one has
// none (the photos are then shown whole); "key" throws inkwire::Error naming that photo
// instead; "none" keys nothing.
KeyedPhotos key_photos(PhotoFolder& photos, const std::string& matte, const PairProgress& progress);

}  // namespace inkwire
