#pragma once
// The camera's exposure and white balance evened across a product's photos (SPEC T19), and
// nothing else. A photo a little brighter or bluer than its neighbours flickers as the product
// turns; but an object turning under fixed lights *should* change from photo to photo (a side
// turns to the lamp, a highlight slides), and evening that away makes a kept photo differ from
// itself. So the camera is read where only the camera changes: the backdrop, lit the same in
// every photo (its colour in the photo's outer border, matte.hpp backdrop_colour). A photo whose
// backdrop departs from its neighbours' (the median of the two either side, in ring order) is
// scaled back by that much, object and all. A backdrop white to the clip shows no exposure: a
// ring with one is left as it was (a rendered product over white, or a studio's blown-out
// sweep), as is a product without mattes.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "common/image.hpp"
#include "server/products/photo_folder.hpp"

namespace inkwire {

inline constexpr float kClippedBackdrop = 250.0f;  // a backdrop channel this bright (0-255) may be clipped

struct CameraGains {
  std::vector<glm::vec3> gains;  // per photo, per channel; 1 where nothing is evened
  std::string unmeasured;        // why nothing was evened, when nothing could be measured
};

// Per photo, the gain that evens the camera's drift in a ring of `backdrops` (RGB 0-255, one per
// photo in ring order; `closed`: the last photo's neighbours include the first).
CameraGains camera_gains(const std::vector<glm::vec3>& backdrops, bool closed);

// Multiplies the colours (not the matte) by `gain`, clamped to 0-255, where the matte is not 0
// (the floor layer there is already relative to the photo's own backdrop).
void apply_gain(Image& photo, const glm::vec3& gain);

// The pipeline's exposure stage, after keying (photo_keying.hpp): per photo, the camera's gain
// evened on `backdrops` (one per photo; empty without mattes: nothing is evened), each row on its
// own (light differs between camera heights: the top row sees the lit top, which is the product's
// look), applied to `photos` and said in a line.
CameraGains even_exposure(PhotoFolder& photos, const std::vector<glm::vec3>& backdrops, const PairProgress& progress);

}  // namespace inkwire
