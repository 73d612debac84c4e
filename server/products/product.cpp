#include "server/products/product.hpp"

#include <optional>

#include "common/error.hpp"
#include "server/products/control_points.hpp"
#include "server/products/exposure.hpp"
#include "server/products/photo_keying.hpp"
#include "server/products/photo_shape.hpp"
#include "server/products/product_samples.hpp"
#include "server/products/turn_angles.hpp"
#include "server/products/tween_budget.hpp"

namespace inkwire {
namespace fs = std::filesystem;

Product product_from_photos(const fs::path& folder, const PhotoProductOptions& o, const PairProgress& progress) {
  if (o.matte != "auto" && o.matte != "key" && o.matte != "none") throw Error("--matte must be auto, key or none");
  if (o.shape != "auto" && o.shape != "off") throw Error("--shape must be auto or off");
  if (o.layout.max_side < 32 || o.layout.max_side > 2048) throw Error("--max-side must be 32..2048");
  return product_from_photo_folder(read_photo_folder(folder, o.layout), o, progress);
}

// The stages in the order they run, each taking what the ones before made. The turn comes first:
// it follows corners on the photos as they were shot, inside mattes of its own.
Product product_from_photo_folder(PhotoFolder photos, const PhotoProductOptions& o, const PairProgress& progress) {
  if (photos.photos.size() < 3) throw Error("a product needs at least 3 photos");
  find_turn_from_matches(photos, progress);
  const KeyedPhotos keyed = key_photos(photos, o.matte, progress);
  const CameraGains camera = even_exposure(photos, keyed.backdrops, progress);
  const std::optional<PhotoShape> shape = o.shape == "auto" ? shape_for_product(photos, keyed.matted, progress) : std::nullopt;
  const CellTracks tracks = control_points(photos, keyed.matted, shape ? &*shape : nullptr, o.control_points, progress);

  Product product;
  product.matted = keyed.matted;
  if (shape) product.shape = report_of(*shape);
  product.data.width = photos.photos[0].width;
  product.data.height = photos.photos[0].height;
  product.data.directions = photos.directions;
  budget_tween_data(product.data, tracks, photos, product.matted, o.max_tween_share, progress);
  take_samples(product, std::move(photos), keyed.backdrops, camera.gains, progress);
  return product;
}

}  // namespace inkwire
