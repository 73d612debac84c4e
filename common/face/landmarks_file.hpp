#pragma once
// The landmarks that travel with a speaker's neutral photo (SPEC F5, asset kind "landmarks"): a
// small JSON file, {"format": "inkwire-face-landmarks", "points": [[x, y], ... 68 pairs]}, in
// the photo's pixels (x right, y down, origin at the top-left corner).
#include <filesystem>
#include <string>

#include "common/face/face_shape.hpp"

namespace inkwire {

std::string landmarks_to_json(const FaceLandmarks& landmarks);
// Throws inkwire::Error with a one-line reason when the text is not 68 finite points.
FaceLandmarks parse_landmarks(const std::string& json);

// Files: written whole (temporary, then renamed); read with a size limit.
void save_landmarks(const std::filesystem::path& file, const FaceLandmarks& landmarks);
FaceLandmarks load_landmarks(const std::filesystem::path& file);

}  // namespace inkwire
