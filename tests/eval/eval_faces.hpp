#pragma once
// `inkwire-eval faces`: expression selection on a labelled set of real faces named
// subjectNN_label.png (the Yale faces). Each subject's `normal` photo is its neutral
// calibration; every other photo with a label the selector knows is classified against it, and
// again as a call's face pictures frame it (15 framings a few pixels apart, against the neutral
// photo read as a call reads it): how much the reading depends on where the picture's edges fall.
// `inkwire-eval face-templates` measures expression templates on such a set (development
// subjects only) and writes the template file the client reconstructs faces with.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/face/face_shape.hpp"

namespace inkwire::eval {

struct FacesOptions {
  std::filesystem::path dataset;
  std::string subjects;   // "01-08", "09-15" or empty for every subject
  int limit = 0;          // 0: every image
  bool details = false;   // per-image features and choices in the JSON
};

nlohmann::json run_faces(const FacesOptions& options);

// Writes the template file: measured templates for the data set's labels, and the visemes,
// laugh and frown composed from measured parts (the file says which is which).
nlohmann::json make_face_templates(const FacesOptions& options, const std::filesystem::path& out);

}  // namespace inkwire::eval
