#include "common/image.hpp"

#include <algorithm>
#include <cmath>
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

Image matte_scaled_up(const Image& matte, int width, int height) {
  if (matte.empty() || width < matte.width || height < matte.height)
    throw Error("matte_scaled_up(): " + std::to_string(matte.width) + "x" + std::to_string(matte.height) + " to " +
                std::to_string(width) + "x" + std::to_string(height));
  Image out(width, height, {0, 0, 0, 255});
  const double sx = double(matte.width) / width, sy = double(matte.height) / height;
  const auto grey = [&](int x, int y) { return double(matte.at(x, y)[0]); };
  for (int y = 0; y < height; ++y) {
    const double fy = std::clamp((y + 0.5) * sy - 0.5, 0.0, double(matte.height - 1));
    const int y0 = int(std::floor(fy)), y1 = std::min(y0 + 1, matte.height - 1);
    const double ty = fy - y0;
    for (int x = 0; x < width; ++x) {
      const double fx = std::clamp((x + 0.5) * sx - 0.5, 0.0, double(matte.width - 1));
      const int x0 = int(std::floor(fx)), x1 = std::min(x0 + 1, matte.width - 1);
      const double tx = fx - x0;
      const double top = grey(x0, y0) * (1 - tx) + grey(x1, y0) * tx;
      const double bottom = grey(x0, y1) * (1 - tx) + grey(x1, y1) * tx;
      uint8_t* p = out.at(x, y);
      p[0] = p[1] = p[2] = uint8_t(std::lround(top * (1 - ty) + bottom * ty));
    }
  }
  return out;
}

}  // namespace inkwire
