#include "server/products/product.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>

#include "common/error.hpp"
#include "protocol/messages.hpp"
#include "server/products/control_points.hpp"
#include "server/products/exposure.hpp"
#include "server/products/matte.hpp"
#include "server/products/photo_folder.hpp"
#include "server/products/photo_shape.hpp"
#include "server/products/turn_angles.hpp"
#include "server/products/tween_budget.hpp"

namespace inkwire {
namespace fs = std::filesystem;

namespace {

// Per photo, the camera's gain (exposure.hpp), each row on its own: light differs between camera
// heights (the top row sees the lit top), which is the product's look. Empty `backdrops` (no
// mattes): nothing is evened.
CameraGains row_gains(const std::vector<glm::vec3>& backdrops, const PhotoFolder& photos) {
  CameraGains all{std::vector<glm::vec3>(photos.photos.size(), glm::vec3(1.0f)), ""};
  if (backdrops.size() != photos.photos.size()) return all.unmeasured = "no mattes, so no backdrop to read the camera on", all;
  const int columns = photos.columns();
  for (int r = 0; r < photos.rows; ++r) {
    const auto first = backdrops.begin() + long(r * columns);
    const CameraGains row = camera_gains({first, first + columns}, photos.closed);
    if (!row.unmeasured.empty()) all.unmeasured = row.unmeasured;
    std::copy(row.gains.begin(), row.gains.end(), all.gains.begin() + long(r * columns));
  }
  return all;
}

// "4.1 9.8 10.2 ..." degrees, one decimal.
std::string degrees_list(const std::vector<float>& degrees) {
  std::string out;
  for (const float d : degrees) {
    char text[16];
    std::snprintf(text, sizeof text, "%s%.1f", out.empty() ? "" : " ", d);
    out += text;
  }
  return out;
}

}  // namespace

std::vector<uint8_t> stored_photo(const Image& image, bool matted) {
  constexpr int kJpegQuality = 90;
  return encode_image(matted ? laid_on_white(image) : image, "jpg", kJpegQuality);
}

std::vector<uint8_t> stored_matte(const Image& image) { return encode_image(image, "png", 0, 3, 1); }

void find_turn_from_matches(PhotoFolder& photos, const PairProgress& progress) {
  if (!photos.even_turn_assumed) return;
  const TurnSteps steps = turn_steps_from_photos(photos);
  if (steps.fitted < 3) {
    if (progress)
      progress(0, int(photos.cells.size()),
               "the turn could not be found from the matches (too few corners followed round): the photos are taken as evenly "
               "spaced (give --step or --arc if they are not)");
    return;
  }
  const bool backwards = steps.direction_known && steps.field_of_view < 0;
  if (!steps.uneven()) {
    if (backwards) set_turn_steps(photos, std::vector<float>(size_t(photos.columns()), -360.0f / float(photos.columns())));
    if (progress) {
      char line[400];
      std::snprintf(line, sizeof line,
                    "the photos are evenly spaced, %s (%d of %d photos tracked: a turn with a free angle per photo fits them within "
                    "%.2f pixels, even steps within %.2f, not clearly worse)",
                    backwards ? "turned the other way" : steps.direction_known ? "turned forward" : "taken as turned forward (--step -N if not)",
                    steps.fitted, photos.columns(), steps.residual, steps.even_residual);
      progress(0, int(photos.cells.size()), line);
    }
    return;
  }
  set_turn_steps(photos, steps.degrees);
  photos.even_turn_assumed = false;
  if (!progress) return;
  std::vector<float> sizes;
  for (const float d : steps.degrees) sizes.push_back(std::abs(d));
  const auto [low, high] = std::minmax_element(sizes.begin(), sizes.end());
  const char* way = !steps.direction_known ? "forward (the perspective is too weak to tell which way: --step -N if it turned the other way)"
                    : steps.degrees[0] < 0  ? "the other way (the camera's azimuth falls)"
                                            : "forward";
  char line[400];
  std::snprintf(line, sizeof line,
                "turn from the matches (%d of %d photos tracked, within %.2f pixels, %.2f if even; perspective %.2f +- %.2f), %s: steps "
                "%.1f to %.1f degrees, %.1f if even: ",
                steps.fitted, photos.columns(), steps.residual, steps.even_residual, steps.field_of_view, steps.field_of_view_error, way, *low, *high,
                360.0 / photos.columns());
  progress(0, int(photos.cells.size()), line + degrees_list(steps.degrees));
}

Product product_from_photos(const fs::path& folder, const PhotoProductOptions& o, const PairProgress& progress) {
  if (o.matte != "auto" && o.matte != "key" && o.matte != "none") throw Error("--matte must be auto, key or none");
  if (o.shape != "auto" && o.shape != "off") throw Error("--shape must be auto or off");
  if (o.layout.max_side < 32 || o.layout.max_side > 2048) throw Error("--max-side must be 32..2048");
  return product_from_photo_folder(read_photo_folder(folder, o.layout), o, progress, folder.string());
}

Product product_from_photo_folder(PhotoFolder photos, const PhotoProductOptions& o, const PairProgress& progress,
                                  const std::string& folder_name) {
  if (photos.photos.size() < 3) throw Error("a product needs at least 3 photos");
  find_turn_from_matches(photos, progress);
  const fs::path folder = folder_name;
  Product product;
  product.data.width = photos.photos[0].width;
  product.data.height = photos.photos[0].height;
  product.data.directions = photos.directions;

  // Mattes: every photo keyed, or none (a product whose samples disagree on having an outline
  // would show one only some of the way round).
  std::vector<glm::vec3> backdrops;
  if (o.matte != "none") {
    std::vector<Image> keyed = photos.photos;
    std::string refusal;
    for (size_t i = 0; i < keyed.size() && refusal.empty(); ++i) {
      const MatteResult r = key_plain_background(keyed[i]);
      if (!r.keyed) refusal = (folder / photos.names[i]).string() + " cannot be keyed: " + r.reason;
      backdrops.push_back(r.backdrop);
    }
    if (refusal.empty()) {
      photos.photos = std::move(keyed);
      product.matted = true;
    } else if (o.matte == "key") {
      throw Error(refusal);
    } else if (progress) {
      progress(0, int(photos.cells.size()), "no mattes: " + refusal + " (the photos are shown whole)");
    }
  }

  // The shape (SPEC T24-T26): from the mattes, where there are mattes of a full turn.
  std::optional<PhotoShape> shape;
  if (o.shape == "auto" && product.matted && photos.closed) {
    try {
      shape = shape_from_photos(photos, kDefaultFieldOfView);
      if (progress) progress(0, int(photos.cells.size()), shape_summary(*shape));
    } catch (const Error& e) {
      if (progress) progress(0, int(photos.cells.size()), std::string("no shape: ") + e.what() + " (control points from the matches alone)");
    }
  }

  // Control points per cell (control_points.hpp), from the matches or the shape.
  const CellTracks tracks = control_points(photos, product.matted, shape ? &*shape : nullptr, o.control_points, progress);

  // Exposure: the camera's gain evened on the backdrop, row by row.
  const int total = int(photos.cells.size());
  const CameraGains camera = row_gains(backdrops, photos);
  const std::vector<glm::vec3>& gains = camera.gains;
  float largest_change = 0;
  for (size_t i = 0; i < gains.size(); ++i) {
    apply_gain(photos.photos[i], gains[i]);
    for (int c = 0; c < 3; ++c) largest_change = std::max(largest_change, std::abs(gains[i][c] - 1.0f));
  }
  if (progress)
    progress(0, total, !camera.unmeasured.empty()
                           ? "exposure left as it was: " + camera.unmeasured
                           : "the camera's exposure evened on the backdrop: the largest change " + std::to_string(int(std::lround(largest_change * 100))) + "%");

  // The budget (tween_budget.hpp): the tween data's share of the first view (the photos' bytes as
  // they will be stored, after the exposure is evened): tween <= share x (photos + mattes + tween).
  size_t photo_bytes = 0;
  for (const Image& photo : photos.photos)
    photo_bytes += stored_photo(photo, product.matted).size() + (product.matted ? stored_matte(photo).size() : 0);
  const double share = std::clamp(double(o.max_tween_share), 0.0, 0.99);
  const size_t budget = size_t(share / (1.0 - share) * double(photo_bytes));
  const BudgetFit fit = fit_tween_budget(product.data, tracks, photos.cells, budget);
  if (progress) {
    const auto percent = [&](size_t bytes) {
      char text[16];
      std::snprintf(text, sizeof text, "%.1f%%", 100.0 * double(bytes) / double(bytes + photo_bytes));
      return std::string(text);
    };
    std::string line = "tween data: " + std::to_string(fit.after) + " bytes, " + percent(fit.after) + " of the first view";
    if (fit.after < fit.before)
      line += " (every cell cut to " + std::to_string(fit.cap) + " points, its outline kept, from " + std::to_string(fit.before) + " bytes, " +
              percent(fit.before) + ")";
    if (fit.after > budget) line += ", over the " + percent(budget) + " kept to: the outlines alone are more";
    progress(0, total, line);
  }
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
    progress(0, total, "zoom: photos " + std::to_string(product.data.width) + "x" + std::to_string(product.data.height) + " first, then " + sizes);
  }
  product.finer = [photos = PhotoFolder{.folder = photos.folder, .names = photos.names}, backdrops, gains,
                   matted = product.matted](size_t index, const Image& first, glm::ivec2 size) {
    Image photo = read_photo_at(photos, index, size);
    if (matted) key_like(photo, first, backdrops[index]);
    apply_gain(photo, gains[index]);
    return photo;
  };
  return product;
}

}  // namespace inkwire
