#include "server/products/product_samples.hpp"

#include <string>

#include "protocol/messages.hpp"
#include "server/products/exposure.hpp"
#include "server/products/matte.hpp"

namespace inkwire {

std::vector<uint8_t> stored_photo(const Image& image, bool matted) {
  constexpr int kJpegQuality = 90;
  return encode_image(matted ? laid_on_white(image) : image, "jpg", kJpegQuality);
}

std::vector<uint8_t> stored_matte(const Image& image) { return encode_image(image, "png", 0, 3, 1); }

void take_samples(Product& product, PhotoFolder photos, const std::vector<glm::vec3>& backdrops, const std::vector<glm::vec3>& gains,
                  const PairProgress& progress) {
  product.images = std::move(photos.photos);
  // Photos say nothing of the camera's distance; a view at the samples' own distance shows them
  // at their own scale, which is all zooming needs.
  product.levels = zoom_levels({product.data.width, product.data.height}, photos.finest);
  // A session lists at most kMaxAssets: the coarser finer levels give way first (zoomed in, the
  // finest is what a customer came for).
  const size_t n = product.images.size(), per_level = n, fixed = n * (product.matted ? 2 : 1) + 1;
  while (!product.levels.empty() && fixed + per_level * product.levels.size() > protocol::kMaxAssets) product.levels.erase(product.levels.begin());
  if (progress && !product.levels.empty()) {
    std::string sizes;
    for (const glm::ivec2& l : product.levels) sizes += (sizes.empty() ? "" : ", ") + std::to_string(l.x) + "x" + std::to_string(l.y);
    progress(0, int(product.data.cells.size()), "zoom: photos " + std::to_string(product.data.width) + "x" + std::to_string(product.data.height) + " first, then " + sizes);
  }
  product.finer = [photos = PhotoFolder{.folder = photos.folder, .names = photos.names}, backdrops, gains,
                   matted = product.matted](size_t index, const Image& first, glm::ivec2 size) {
    Image photo = read_photo_at(photos, index, size);
    if (matted) key_like(photo, first, backdrops[index]);
    apply_gain(photo, gains[index]);
    return photo;
  };
}

}  // namespace inkwire
