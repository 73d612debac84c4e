#pragma once
// 8-bit RGBA images, rows top-down (the way files and people see them), read and written
// through OpenImageIO and OpenCV (common/image_io.cpp); the WebAssembly build reads them with
// stb_image (common/image_io_web.cpp) and writes none.
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

namespace inkwire {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // RGBA, row 0 is the top row

  Image() = default;
  Image(int w, int h, glm::u8vec4 fill = {0, 0, 0, 0});
  bool empty() const { return width == 0 || height == 0; }
  uint8_t* at(int x, int y) { return &pixels[(size_t(y) * width + x) * 4]; }
  const uint8_t* at(int x, int y) const { return &pixels[(size_t(y) * width + x) * 4]; }
  glm::u8vec4 rgba(int x, int y) const {
    const uint8_t* p = at(x, y);
    return {p[0], p[1], p[2], p[3]};
  }
};

// Images larger than this on either side are refused when read from outside.
inline constexpr int kMaxImageSide = 16384;

// Converts any channel count to RGBA (grey -> RGB, missing alpha -> opaque). Throws
// inkwire::Error with a one-line reason on unreadable, truncated or oversized files.
Image load_image(const std::filesystem::path& file);
Image load_image_from_memory(std::span<const uint8_t> encoded, const std::string& name_for_errors);

// Encodes in memory, never through a file: "jpg" (colour, at `quality` 1..100) or "png";
// `channels` 3 is the colour, 1 the channel `first_channel` alone as grey (a matte from alpha).
// Throws inkwire::Error when the encoder fails.
std::vector<uint8_t> encode_image(const Image& image, const std::string& format, int quality = 90, int first_channel = 0, int channels = 3);

// Writes PNG (or any format OpenImageIO knows by extension). `keep_alpha` false drops alpha.
void save_image(const Image& image, const std::filesystem::path& file, bool keep_alpha = true);

// The width x height rectangle of `image` whose top-left pixel is (x, y). Throws inkwire::Error
// when it does not lie inside the image.
Image cropped(const Image& image, int x, int y, int width, int height);

// Images of one height laid left to right (contact sheets, side-by-side videos). Throws
// inkwire::Error when there are none or their heights differ.
Image side_by_side(const std::vector<Image>& panels);
// The same under a strip naming each panel, for sheets and videos read without the command that
// made them. Text that cannot be drawn (no font) leaves its place in the strip blank.
Image side_by_side(const std::vector<Image>& panels, const std::vector<std::string>& captions);

// Reverses row order: GL read-backs are bottom-up.
void flip_rows(Image& image);

// A copy scaled to `width` x `height` (area averaging when shrinking, bilinear when growing).
Image resized(const Image& image, int width, int height);

// A matte (grey in red) scaled up to `width` x `height` bilinearly, each pixel's centre mapped
// back into the matte and clamped at its border, in double: how the server lays a finer zoom
// level's photo over its first level's matte (server/products/matte.cpp key_like()) and how the
// clients take it off again (client/render/tween/matte_sample.cpp, and step for step the
// browser's client/web/render/tween/matte_sample.js, pinned by tests/golden/warp-vectors.json).
Image matte_scaled_up(const Image& matte, int width, int height);

}  // namespace inkwire
