#pragma once
// The pipeline's last stage, after the budget (tween_budget.hpp): the product's samples as they
// are stored. The photos keyed and evened become its first view; their finer levels (SPEC T18)
// are listed and made alike when stored.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "common/image.hpp"
#include "server/products/photo_folder.hpp"
#include "server/products/product.hpp"

namespace inkwire {

// A sample as a product stores it: the photo (JPEG; a keyed one on white with its floor layer,
// as a shop shows it and as compresses best) and its matte (PNG of the alpha).
std::vector<uint8_t> stored_photo(const Image& image, bool matted);
std::vector<uint8_t> stored_matte(const Image& image);

// Takes `photos` as `product`'s samples (`product.matted`: keyed against `backdrops`; their
// exposure evened by `gains`, one per photo): the zoom levels a session can list, said in a
// line, and how a finer level of each is read, keyed and evened as the first was.
void take_samples(Product& product, PhotoFolder photos, const std::vector<glm::vec3>& backdrops, const std::vector<glm::vec3>& gains,
                  const PairProgress& progress);

}  // namespace inkwire
