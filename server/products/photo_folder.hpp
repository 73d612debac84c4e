#pragma once
// A shop owner's folder of turntable photos, read and checked: photos in file-name order
// (JPEG, PNG, TIFF, BMP, WebP), turned upright by their EXIF orientation, scaled to one size;
// directions equally spaced over a full turn, over `arc`, by `step` (negative when the turntable
// turned the other way: the camera's azimuth falls from photo to photo), or from a Middlebury-style
// `*_par.txt` calibration in the folder. Anything else in the folder is refused by name, except
// hidden files and the calibration's companions (*.txt).
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "common/image.hpp"

namespace inkwire {

struct PhotoFolder {
  std::vector<std::string> names;       // file names, in ring order
  std::vector<Image> photos;            // RGBA, all one size
  std::vector<glm::vec3> directions;    // unit, from the object toward the camera
  std::vector<std::vector<uint16_t>> pairs;  // neighbouring photos to tween between
  bool closed = false;                  // the photos go all the way round
};

// Throws inkwire::Error with a one-line reason naming the file at fault: an empty or missing
// folder, fewer than 3 photos, an unreadable photo, a photo whose shape differs from the first,
// a file that is not a photo, steps that do not fit.
PhotoFolder read_photo_folder(const std::filesystem::path& folder, float step_degrees, float arc_degrees, int max_side);

// A photo turned upright by its EXIF orientation (1-8), as a viewer shows it.
Image load_upright_photo(const std::filesystem::path& file);

}  // namespace inkwire
