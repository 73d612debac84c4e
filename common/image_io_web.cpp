// Image decoding in the WebAssembly build: stb_image (Debian's libstb-dev, header-only) where the
// native build has OpenImageIO and OpenCV (common/image_io.cpp). Only reading: the browser's
// module draws and never writes files.
#include <fstream>
#include <iterator>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#include <stb_image.h>

#include "common/error.hpp"
#include "common/image.hpp"

namespace inkwire {

Image load_image_from_memory(std::span<const uint8_t> encoded, const std::string& name) {
  if (encoded.empty()) throw Error(name + ": no image bytes");
  if (encoded.size() > size_t(INT32_MAX)) throw Error(name + ": image file too large");
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels))
    throw Error(name + ": not an image in a format that can be read (PNG, JPEG, BMP)");
  if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide)
    throw Error(name + ": image size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1.." + std::to_string(kMaxImageSide));
  stbi_uc* pixels = stbi_load_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels, 4);
  if (!pixels) throw Error(name + ": " + (stbi_failure_reason() ? stbi_failure_reason() : "cannot be decoded"));
  Image image(width, height);
  std::copy_n(pixels, image.pixels.size(), image.pixels.begin());
  stbi_image_free(pixels);
  return image;
}

Image load_image(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(file.string() + ": cannot be read");
  const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return load_image_from_memory(bytes, file.string());
}

}  // namespace inkwire
