#include "server/products/photo_keying.hpp"

#include "common/error.hpp"
#include "server/products/matte.hpp"

namespace inkwire {

KeyedPhotos key_photos(PhotoFolder& photos, const std::string& matte, const PairProgress& progress) {
  KeyedPhotos out;
  if (matte == "none") return out;
  std::vector<Image> keyed = photos.photos;
  std::string refusal;
  for (size_t i = 0; i < keyed.size() && refusal.empty(); ++i) {
    const MatteResult r = key_plain_background(keyed[i]);
    if (!r.keyed) refusal = (photos.folder / photos.names[i]).string() + " cannot be keyed: " + r.reason;
    out.backdrops.push_back(r.backdrop);
  }
  if (refusal.empty()) {
    photos.photos = std::move(keyed);
    out.matted = true;
    return out;
  }
  if (matte == "key") throw Error(refusal);
  if (progress) progress(0, int(photos.cells.size()), "no mattes: " + refusal + " (the photos are shown whole)");
  out.backdrops.clear();
  return out;
}

}  // namespace inkwire
