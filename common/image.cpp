#include "common/image.hpp"

#include <algorithm>
#include <cstring>

#include "common/error.hpp"

namespace inkwire {

Image::Image(int w, int h, glm::u8vec4 fill) : width(w), height(h), pixels(size_t(w) * h * 4) {
  for (size_t i = 0; i < pixels.size(); i += 4) std::memcpy(&pixels[i], &fill[0], 4);
}

void flip_rows(Image& image) {
  const size_t row = size_t(image.width) * 4;
  for (int y = 0; y < image.height / 2; ++y)
    std::swap_ranges(image.pixels.begin() + y * row, image.pixels.begin() + (y + 1) * row,
                     image.pixels.begin() + (image.height - 1 - y) * row);
}

Image cropped(const Image& image, int x, int y, int width, int height) {
  if (x < 0 || y < 0 || width <= 0 || height <= 0 || x + width > image.width || y + height > image.height)
    throw Error("cropped(): the rectangle is not inside the image");
  Image out(width, height);
  for (int row = 0; row < height; ++row) std::copy_n(image.at(x, y + row), size_t(width) * 4, out.at(0, row));
  return out;
}

Image side_by_side(const std::vector<Image>& panels) {
  if (panels.empty()) throw Error("side_by_side(): no images");
  int width = 0;
  for (const Image& p : panels) {
    if (p.height != panels.front().height) throw Error("side_by_side(): the images differ in height");
    width += p.width;
  }
  Image out(width, panels.front().height);
  int x0 = 0;
  for (const Image& p : panels) {
    for (int y = 0; y < p.height; ++y) std::copy_n(p.at(0, y), size_t(p.width) * 4, out.at(x0, y));
    x0 += p.width;
  }
  return out;
}

}  // namespace inkwire
