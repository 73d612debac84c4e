#include "server/products/photo_folder.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <OpenImageIO/imageio.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <opencv2/core.hpp>

#include "common/error.hpp"
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

// The calibrated directions turned so the ring lies about +Y with the first photo at azimuth 0,
// the frame the clients' orbit uses (a lab's world frame is anyone's guess).
std::vector<glm::vec3> ring_frame(const std::vector<glm::vec3>& directions) {
  glm::vec3 axis(0.0f);
  for (size_t i = 0; i + 1 < directions.size(); ++i) axis += glm::cross(directions[i], directions[i + 1]);
  if (glm::length(axis) < 1e-6f) throw Error("the calibrated cameras do not go round the object");
  const glm::vec3 y = glm::normalize(axis);
  const glm::vec3 z = glm::normalize(directions[0] - glm::dot(directions[0], y) * y);
  const glm::vec3 x = glm::cross(y, z);
  std::vector<glm::vec3> out;
  for (const glm::vec3& d : directions) out.push_back(glm::normalize(glm::vec3(glm::dot(d, x), glm::dot(d, y), glm::dot(d, z))));
  return out;
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

PhotoFolder read_photo_folder(const fs::path& folder, float step_degrees, float arc_degrees, int max_side) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw Error(folder.string() + " is not a folder");
  if (std::abs(step_degrees) > 180) throw Error("--step must be -180..180 degrees");
  if (std::abs(arc_degrees) > 360) throw Error("--arc must be -360..360 degrees");
  if (step_degrees != 0 && arc_degrees != 0) throw Error("give --step or --arc, not both");

  PhotoFolder out;
  std::vector<fs::path> files;
  bool calibrated = false;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const fs::path& file = entry.path();
    if (file.filename().string().ends_with("_par.txt")) calibrated = true;
    if (is_companion(file)) continue;
    if (!entry.is_regular_file()) throw Error(file.string() + " is not a photo (a folder of photos holds no folders)");
    if (!is_photo_name(file)) throw Error(file.string() + " is not a photo (JPEG, PNG, TIFF, BMP or WebP)");
    files.push_back(file);
  }
  if (ec) throw Error("cannot list " + folder.string() + ": " + ec.message());
  std::sort(files.begin(), files.end());

  if (calibrated) {
    // The calibration names the photos and their order; photos it does not name are refused.
    const PhotoRing ring = load_photo_ring(folder);
    std::set<std::string> named(ring.names.begin(), ring.names.end());
    for (const fs::path& f : files)
      if (!named.count(f.filename().string())) throw Error(f.string() + " is not in the folder's calibration");
    out.names = ring.names;
    out.directions = ring_frame(ring.directions);
  } else {
    for (const fs::path& f : files) out.names.push_back(f.filename().string());
  }
  const int n = int(out.names.size());
  if (n < 3) throw Error(folder.string() + " holds " + std::to_string(n) + " photo" + (n == 1 ? "" : "s") + "; a turntable needs at least 3");
  if (n > 360) throw Error(folder.string() + " holds " + std::to_string(n) + " photos; at most 360 (one per degree)");

  if (!calibrated) {
    const float step = step_degrees != 0 ? step_degrees : arc_degrees != 0 ? arc_degrees / float(n - 1) : 360.0f / float(n);
    if (std::abs(step) * float(n - 1) > 360.0f + 1e-3f)
      throw Error(std::to_string(n) + " photos " + std::to_string(step) + " degrees apart turn more than once round");
    for (int i = 0; i < n; ++i) {
      const float az = glm::radians(step * float(i));
      out.directions.push_back({std::sin(az), 0.0f, std::cos(az)});
    }
  }
  // Neighbours in order; the last and the first too when the photos go all the way round (the
  // gap that closes the ring is no wider than one and a half of the others).
  std::vector<float> steps;
  for (int i = 0; i + 1 < n; ++i) {
    out.pairs.push_back({uint16_t(i), uint16_t(i + 1)});
    steps.push_back(glm::degrees(std::acos(std::clamp(glm::dot(out.directions[size_t(i)], out.directions[size_t(i + 1)]), -1.0f, 1.0f))));
  }
  std::sort(steps.begin(), steps.end());
  const float closing = glm::degrees(std::acos(std::clamp(glm::dot(out.directions.back(), out.directions.front()), -1.0f, 1.0f)));
  out.closed = closing > 1e-3f && closing <= 1.5f * steps[steps.size() / 2] + 1e-3f;
  if (out.closed) out.pairs.push_back({uint16_t(n - 1), uint16_t(0)});

  // Every photo upright and at the first one's shape, scaled to at most max_side.
  glm::ivec2 size(0);
  for (const std::string& name : out.names) {
    const fs::path file = folder / name;
    Image photo;
    try {
      photo = load_upright_photo(file);
    } catch (const Error& e) {
      throw Error(file.string() + " cannot be read: " + e.what());
    }
    if (size.x == 0) {
      const float scale = std::min(1.0f, float(max_side) / float(std::max(photo.width, photo.height)));
      size = {std::max(1, int(std::lround(photo.width * scale))), std::max(1, int(std::lround(photo.height * scale)))};
    } else {
      const float aspect = float(photo.width) / float(photo.height), wanted = float(size.x) / float(size.y);
      if (std::abs(aspect / wanted - 1.0f) > 0.02f)
        throw Error(file.string() + " is " + std::to_string(photo.width) + "x" + std::to_string(photo.height) +
                    ", not the shape of the first photo (" + out.names[0] + ")");
    }
    if (photo.width != size.x || photo.height != size.y) photo = resized(photo, size.x, size.y);
    for (size_t i = 3; i < photo.pixels.size(); i += 4) photo.pixels[i] = 255;  // photos are opaque until keyed
    out.photos.push_back(std::move(photo));
  }
  return out;
}

}  // namespace inkwire
