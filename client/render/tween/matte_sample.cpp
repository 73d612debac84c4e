#include "client/render/tween/matte_sample.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/distance_field.hpp"
#include "common/error.hpp"

namespace inkwire {

Image object_on_matte(Image photo, const Image& matte) {
  const float aspect = float(photo.width) / float(photo.height), own = float(matte.width) / float(matte.height);
  if (matte.empty() || matte.width > photo.width || matte.height > photo.height || std::abs(aspect / own - 1.0f) > 0.01f)
    throw Error("a " + std::to_string(matte.width) + "x" + std::to_string(matte.height) + " matte does not fit its " +
                std::to_string(photo.width) + "x" + std::to_string(photo.height) + " photo");
  const Image alpha = matte.width == photo.width && matte.height == photo.height ? matte : matte_scaled_up(matte, photo.width, photo.height);
  for (size_t i = 0; i < photo.pixels.size(); i += 4) {
    const int a = alpha.pixels[i];
    photo.pixels[i + 3] = uint8_t(a);
    // Too little object in a pixel to tell its colour from the white: left as it is (the
    // distance to the outline, not this colour, decides such a pixel in matte_sample()).
    if (a >= 32 && a < 255)
      for (size_t c = 0; c < 3; ++c) photo.pixels[i + c] = uint8_t(std::clamp((int(photo.pixels[i + c]) * 255 - (255 - a) * 255 + a / 2) / a, 0, 255));
  }
  return photo;
}

Image matte_sample(const Image& image, double scale) {
  const int w = image.width, h = image.height;
  const size_t n = size_t(w) * size_t(h);
  std::vector<uint8_t> inside(n), outside(n);
  for (size_t i = 0; i < n; ++i) {
    inside[i] = image.pixels[4 * i + 3] >= 128 ? 1 : 0;
    outside[i] = 1 - inside[i];
  }
  // Distances to the nearest pixel of the other side, and which object pixel is nearest (for
  // bleeding its colour).
  const DistanceField to_object = distance_to_seeds(inside, w, h), to_background = distance_to_seeds(outside, w, h);
  Image out = image;
  for (size_t i = 0; i < n; ++i) {
    // The outline lies half a pixel beyond the last pixel of either side; a pixel the matte
    // covers in part is that far across it, so a sample shown as it is keeps its soft edge.
    const int alpha = image.pixels[4 * i + 3];
    double d = (inside[i] ? to_background.distance[i] - 0.5 : 0.5 - to_object.distance[i]) / scale;
    if (alpha > 0 && alpha < 255 && std::abs(d) <= 1.0) d = alpha / 255.0 - 0.5;
    // Too little of the object in it to trust its colour: the nearest object pixel's, up to
    // kBleedPixels out (the blend reads a sample's colour only where it sees the object or
    // nearly); further out the colour is the floor layer on white (SPEC T16), kept, soft edge
    // or not: a finer level's scaled-up soft edge reaches further, and colour bled there
    // would show as floor (yellow dots along a zoomed-in outline).
    if (alpha < 32 && to_object.distance[i] <= kBleedPixels * scale)
      std::copy_n(&image.pixels[4 * size_t(to_object.nearest[i])], 3, &out.pixels[4 * i]);
    out.pixels[4 * i + 3] = uint8_t(std::lround(std::clamp(0.5 + d / (2.0 * kMatteRange), 0.0, 1.0) * 255.0));
  }
  return out;
}

Image without_floor(Image sample) {
  for (size_t i = 0; i < sample.pixels.size(); i += 4)
    if (sample.pixels[i + 3] == 0) sample.pixels[i] = sample.pixels[i + 1] = sample.pixels[i + 2] = 255;
  return sample;
}

}  // namespace inkwire
