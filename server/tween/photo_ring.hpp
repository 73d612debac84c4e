#pragma once
// A real turntable (SPEC T1b): photos taken around an object with their camera calibration, in
// the Middlebury multi-view layout (templeRing, dinoRing): a `*_par.txt` file whose first line
// is the image count and every further line "name.png k11..k33 r11..r33 t1 t2 t3" (projection
// K [R t]). View directions come from the calibration: the camera looks along R's third row.
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace inkwire {

struct PhotoRing {
  std::filesystem::path folder;
  std::vector<std::string> names;       // image file names, in the calibration file's order
  std::vector<glm::vec3> directions;    // unit, from the object toward each camera
};

// Throws inkwire::Error with a one-line reason when there is no calibration file, a line is
// malformed, a rotation is not a rotation, or a named image is missing.
PhotoRing load_photo_ring(const std::filesystem::path& folder);

// Three photos i, j, k in ring order whose neighbours are both at most `max_step_degrees` apart:
// the middle one can be synthesised from the outer two.
struct RingTriple {
  int before, middle, after;
  float t;  // where the middle view lies between the outer two (angle fraction)
};
std::vector<RingTriple> ring_triples(const PhotoRing& ring, float max_step_degrees = 12.0f);

}  // namespace inkwire
