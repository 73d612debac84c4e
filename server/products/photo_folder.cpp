#include "server/products/photo_folder.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include <OpenImageIO/imageio.h>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <opencv2/core.hpp>

#include "common/error.hpp"
#include "server/products/calibrated_ring.hpp"
#include "server/tween/photo_ring.hpp"

namespace inkwire {
namespace fs = std::filesystem;
namespace {

bool is_photo_name(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  static const std::set<std::string> photo = {".jpg", ".jpeg", ".png", ".tif", ".tiff", ".bmp", ".webp"};
  return photo.count(ext) > 0;
}

bool is_companion(const fs::path& file) {
  const std::string name = file.filename().string();
  return name.empty() || name[0] == '.' || name == "Thumbs.db" || file.extension() == ".txt";
}

// 12 for a folder named "row12" (any case), 0 for any other name.
int row_number(const std::string& name) {
  if (name.size() < 4 || name.size() > 6) return 0;
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (lower.compare(0, 3, "row") != 0 || !std::all_of(lower.begin() + 3, lower.end(), [](unsigned char c) { return std::isdigit(c); }))
    return 0;
  return std::stoi(lower.substr(3));
}

struct Listing {
  std::vector<fs::path> photos;  // in file-name order
  std::vector<std::pair<int, fs::path>> row_folders;
  fs::path calibration;          // a *_par.txt there
};

// What a folder holds: photos, row folders (when `rows_allowed`), companions; anything else is
// refused by name.
Listing list_folder(const fs::path& folder, bool rows_allowed) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw Error(folder.string() + " is not a folder");
  Listing out;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const fs::path& file = entry.path();
    if (file.filename().string().ends_with("_par.txt")) out.calibration = file;
    if (is_companion(file)) continue;
    if (entry.is_directory()) {
      const int row = rows_allowed ? row_number(file.filename().string()) : 0;
      if (row == 0)
        throw Error(file.string() + " is not a photo (a folder of photos holds photos, or row folders row1, row2, ... from the lowest camera up)");
      out.row_folders.push_back({row, file});
      continue;
    }
    if (!entry.is_regular_file()) throw Error(file.string() + " is not a photo");
    if (!is_photo_name(file)) throw Error(file.string() + " is not a photo (JPEG, PNG, TIFF, BMP or WebP)");
    out.photos.push_back(file);
  }
  if (ec) throw Error("cannot list " + folder.string() + ": " + ec.message());
  std::sort(out.photos.begin(), out.photos.end());
  std::sort(out.row_folders.begin(), out.row_folders.end());
  return out;
}

// Row r's elevation: as given, else level first and then 15 degrees apart (closer when more
// than 6 rows would pass overhead), the spacing spin-viewer photographers commonly use.
std::vector<float> row_elevations(const PhotoLayout& layout, int rows) {
  if (!layout.elevations.empty()) {
    if (int(layout.elevations.size()) != rows)
      throw Error(std::to_string(layout.elevations.size()) + " elevations given for " + std::to_string(rows) + " rows");
    for (size_t r = 0; r < layout.elevations.size(); ++r) {
      if (!(std::abs(layout.elevations[r]) <= 90.0f)) throw Error("elevations must be -90..90 degrees");
      if (r > 0 && !(layout.elevations[r] > layout.elevations[r - 1]))
        throw Error("elevations go from the lowest row up: each higher than the one before");
    }
    return layout.elevations;
  }
  const float spacing = std::min(15.0f, 90.0f / float(rows));
  std::vector<float> out;
  for (int r = 0; r < rows; ++r) out.push_back(spacing * float(r));
  return out;
}

Image load_photo(const fs::path& file) {
  try {
    return load_upright_photo(file);
  } catch (const Error& e) {
    throw Error(file.string() + " cannot be read: " + e.what());
  }
}

// `photo` at `size`, opaque (photos are opaque until keyed).
Image opaque_at(Image photo, glm::ivec2 size) {
  if (photo.width != size.x || photo.height != size.y) photo = resized(photo, size.x, size.y);
  for (size_t i = 3; i < photo.pixels.size(); i += 4) photo.pixels[i] = 255;
  return photo;
}

}  // namespace

Image load_upright_photo(const fs::path& file) {
  Image image = load_image(file);
  int orientation = 1;
  if (auto in = OIIO::ImageInput::open(file.string())) {
    orientation = in->spec().get_int_attribute("Orientation", 1);
    in->close();
  }
  if (orientation <= 1 || orientation > 8) return image;
  cv::Mat source(image.height, image.width, CV_8UC4, image.pixels.data()), turned;
  switch (orientation) {
    case 2: cv::flip(source, turned, 1); break;
    case 3: cv::rotate(source, turned, cv::ROTATE_180); break;
    case 4: cv::flip(source, turned, 0); break;
    case 5: cv::transpose(source, turned); break;
    case 6: cv::rotate(source, turned, cv::ROTATE_90_CLOCKWISE); break;
    case 7: cv::transpose(source, turned), cv::rotate(turned, turned, cv::ROTATE_180); break;
    case 8: cv::rotate(source, turned, cv::ROTATE_90_COUNTERCLOCKWISE); break;
  }
  Image out(turned.cols, turned.rows);
  std::copy_n(turned.ptr<uint8_t>(0), out.pixels.size(), out.pixels.data());
  return out;
}

std::vector<glm::ivec2> zoom_levels(glm::ivec2 first, glm::ivec2 finest) {
  // Sizes in proportion to the finest, so every level frames the photo alike.
  const float first_scale = float(std::max(first.x, first.y)) / float(std::max(finest.x, finest.y));
  std::vector<glm::ivec2> levels;
  for (float scale = 2.0f * first_scale; scale < 1.0f; scale *= 2.0f)
    levels.push_back({std::max(1, int(std::lround(float(finest.x) * scale))), std::max(1, int(std::lround(float(finest.y) * scale)))});
  levels.push_back(finest);
  const float kWorthALevel = 1.25f;
  auto hardly_finer = [&](glm::ivec2 level, glm::ivec2 than) { return float(std::max(level.x, level.y)) < kWorthALevel * float(std::max(than.x, than.y)); };
  if (hardly_finer(finest, first)) return {};
  for (size_t i = 0; i + 1 < levels.size();)
    if (hardly_finer(levels[i + 1], levels[i])) levels.erase(levels.begin() + long(i));
    else ++i;
  return levels;
}

Image read_photo_at(const PhotoFolder& photos, size_t index, glm::ivec2 size) {
  return opaque_at(load_photo(photos.folder / photos.names.at(index)), size);
}

std::vector<std::vector<uint16_t>> row_triangles(int rows, int columns, bool closed) {
  std::vector<std::vector<uint16_t>> cells;
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c < columns - (closed ? 0 : 1); ++c) {
      const int next = (c + 1) % columns;
      const auto at = [&](int row, int column) { return uint16_t(row * columns + column); };
      cells.push_back({at(r, c), at(r, next), at(r + 1, c)});
      cells.push_back({at(r + 1, next), at(r + 1, c), at(r, next)});
    }
  return cells;
}

PhotoFolder read_photo_folder(const fs::path& folder, const PhotoLayout& layout) {
  if (std::abs(layout.step_degrees) > 180) throw Error("--step must be -180..180 degrees");
  if (std::abs(layout.arc_degrees) > 360) throw Error("--arc must be -360..360 degrees");
  if (layout.step_degrees != 0 && layout.arc_degrees != 0) throw Error("give --step or --arc, not both");
  if (layout.rows < 0 || layout.rows > 36) throw Error("--rows must be 1..36");

  const Listing listing = list_folder(folder, true);
  const fs::path calibration = !layout.calibration.empty() ? layout.calibration : layout.folder_calibration ? listing.calibration : fs::path();
  PhotoFolder out;
  RingFrame frame;                     // with a calibration
  std::vector<RingCamera> calibrated;  // its cameras, in the photos' order
  std::vector<std::vector<std::string>> rows;  // names relative to the folder, per row
  if (!listing.row_folders.empty()) {
    if (!listing.photos.empty())
      throw Error(listing.photos.front().string() + " is beside row folders: put every photo in its row's folder (row1, row2, ...)");
    if (!calibration.empty()) throw Error(folder.string() + ": a calibration file describes one ring of photos, not rows");
    for (size_t r = 0; r < listing.row_folders.size(); ++r)
      if (listing.row_folders[r].first != int(r) + 1)
        throw Error(folder.string() + " has row folders " + listing.row_folders[r].second.filename().string() + " but no row" +
                    std::to_string(r + 1) + " (numbered from row1, the lowest camera, without gaps)");
    if (layout.rows != 0 && layout.rows != int(listing.row_folders.size()))
      throw Error("--rows " + std::to_string(layout.rows) + " but " + folder.string() + " holds " + std::to_string(listing.row_folders.size()) + " row folders");
    for (const auto& [number, row_folder] : listing.row_folders) {
      const Listing row = list_folder(row_folder, false);
      if (!row.calibration.empty() && layout.folder_calibration)
        throw Error(row_folder.string() + ": a calibration file describes one ring of photos, not rows");
      rows.emplace_back();
      for (const fs::path& f : row.photos) rows.back().push_back(row_folder.filename().string() + "/" + f.filename().string());
    }
  } else if (!calibration.empty()) {
    // The calibration names the photos and their order; photos it does not name are refused.
    if (layout.rows > 1) throw Error(folder.string() + ": a calibration file describes one ring of photos, not rows");
    const PhotoRing ring = load_photo_ring(folder, calibration);
    std::set<std::string> named(ring.names.begin(), ring.names.end());
    for (const fs::path& f : listing.photos)
      if (!named.count(f.filename().string())) throw Error(f.string() + " is not in the folder's calibration");
    // Neighbours by azimuth, not by the file's order: a lab lists its photos as it took them, in
    // sweeps that jump and turn back (templeRing: 0 to 30 degrees, then 76 to 122, ...), and a
    // pair between photos 100 degrees apart would be tweened across the whole gap.
    frame = ring_frame(ring);
    const std::vector<glm::vec3>& directions = frame.directions;
    std::vector<size_t> order(directions.size());
    std::iota(order.begin(), order.end(), size_t(0));
    const auto azimuth = [&](size_t i) {
      const float a = std::atan2(directions[i].x, directions[i].z);
      return a < -1e-5f ? a + glm::two_pi<float>() : std::max(a, 0.0f);  // the first photo's 0 first
    };
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return azimuth(a) < azimuth(b); });
    rows.emplace_back();
    for (size_t i : order) {
      rows.back().push_back(ring.names[i]);
      out.directions.push_back(directions[i]);
      calibrated.push_back(ring.cameras[i]);
    }
  } else {
    const int count = std::max(layout.rows, 1), n = int(listing.photos.size());
    if (n % count != 0)
      throw Error(folder.string() + " holds " + std::to_string(n) + " photos, which do not make " + std::to_string(count) + " rows of one length");
    for (int r = 0; r < count; ++r) {
      rows.emplace_back();
      for (int c = 0; c < n / count; ++c) rows.back().push_back(listing.photos[size_t(r * (n / count) + c)].filename().string());
    }
  }
  const int columns = int(rows.front().size());
  for (size_t r = 0; r < rows.size(); ++r) {
    const std::string where = rows.size() > 1 ? folder.string() + " row " + std::to_string(r + 1) : folder.string();
    const int n = int(rows[r].size());
    if (n < 3) throw Error(where + " holds " + std::to_string(n) + " photo" + (n == 1 ? "" : "s") + "; a turntable needs at least 3");
    if (n != columns)
      throw Error(where + " holds " + std::to_string(n) + " photos and row 1 " + std::to_string(columns) + ": every row turns in the same steps");
    for (const std::string& name : rows[r]) out.names.push_back(name);
  }
  const int n = int(out.names.size());
  if (n > 360) throw Error(folder.string() + " holds " + std::to_string(n) + " photos; at most 360 (one per degree)");
  out.rows = int(rows.size());

  if (!calibration.empty()) {
    // Neighbours in order; the last and the first too when the photos go all the way round (the
    // gap that closes the ring is no wider than one and a half of the others).
    std::vector<float> steps;
    for (int i = 0; i + 1 < n; ++i)
      steps.push_back(glm::degrees(std::acos(std::clamp(glm::dot(out.directions[size_t(i)], out.directions[size_t(i + 1)]), -1.0f, 1.0f))));
    std::sort(steps.begin(), steps.end());
    const float closing = glm::degrees(std::acos(std::clamp(glm::dot(out.directions.back(), out.directions.front()), -1.0f, 1.0f)));
    out.closed = closing > 1e-3f && closing <= 1.5f * steps[steps.size() / 2] + 1e-3f;
  } else {
    out.even_turn_assumed = layout.step_degrees == 0 && layout.arc_degrees == 0;
    const float step = layout.step_degrees != 0 ? layout.step_degrees
                       : layout.arc_degrees != 0 ? layout.arc_degrees / float(columns - 1)
                                                 : 360.0f / float(columns);
    if (std::abs(step) * float(columns - 1) > 360.0f + 1e-3f)
      throw Error(std::to_string(columns) + " photos " + std::to_string(step) + " degrees apart turn more than once round");
    const float closing = 360.0f - std::abs(step) * float(columns - 1);
    out.closed = closing > 1e-3f && closing <= 1.5f * std::abs(step) + 1e-3f;
    const std::vector<float> elevations = row_elevations(layout, out.rows);
    for (int r = 0; r < out.rows; ++r)
      for (int c = 0; c < columns; ++c) {
        const float az = glm::radians(step * float(c)), el = glm::radians(elevations[size_t(r)]);
        out.directions.push_back({std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)});
      }
  }
  if (out.rows == 1) {
    for (int i = 0; i + 1 < n; ++i) out.cells.push_back({uint16_t(i), uint16_t(i + 1)});
    if (out.closed) out.cells.push_back({uint16_t(n - 1), uint16_t(0)});
  } else {
    out.cells = row_triangles(out.rows, columns, out.closed);
  }

  // Every photo upright and at the first one's shape, scaled to the first level.
  out.folder = folder;
  glm::ivec2 size(0);
  for (const std::string& name : out.names) {
    const fs::path file = folder / name;
    Image photo = load_photo(file);
    if (size.x == 0) {
      auto scaled = [&](int side) {
        const float scale = std::min(1.0f, float(side) / float(std::max(photo.width, photo.height)));
        return glm::ivec2(std::max(1, int(std::lround(photo.width * scale))), std::max(1, int(std::lround(photo.height * scale))));
      };
      size = scaled(std::min(layout.max_side, kFirstSide));
      out.finest = scaled(layout.max_side);
      if (!calibrated.empty()) out.calibration = calibrated_camera(frame, calibrated, {photo.width, photo.height}, size);
    } else {
      const float aspect = float(photo.width) / float(photo.height), wanted = float(size.x) / float(size.y);
      if (std::abs(aspect / wanted - 1.0f) > 0.02f)
        throw Error(file.string() + " is " + std::to_string(photo.width) + "x" + std::to_string(photo.height) +
                    ", not the shape of the first photo (" + out.names[0] + ")");
    }
    out.photos.push_back(opaque_at(std::move(photo), size));
  }
  return out;
}

}  // namespace inkwire
