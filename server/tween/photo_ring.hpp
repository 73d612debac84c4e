#pragma once
// A real turntable (SPEC T1b): photos taken around an object with their camera calibration, in
// the Middlebury multi-view layout (templeRing, dinoRing): a `*_par.txt` file whose first line
// is the image count and every further line "name.png k11..k33 r11..r33 t1 t2 t3" (projection
// K [R t]). View directions come from the calibration: the camera looks along R's third row.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace inkwire {

// A calibrated camera: a world point X lands at pixel K (R X + t) (after dividing by depth).
struct RingCamera {
  glm::mat3 k{1.0f}, r{1.0f};
  glm::vec3 t{0.0f};
};

struct PhotoRing {
  std::filesystem::path folder;
  std::vector<std::string> names;       // image file names, in the calibration file's order
  std::vector<glm::vec3> directions;    // unit, from the object toward each camera
  std::vector<RingCamera> cameras;      // as calibrated, in pixels of the photos
};

// The fundamental matrix from camera `from` to camera `to`: a pixel p of `from` can only match
// pixels q of `to` on the line F p (q^T F p = 0), whatever the depth of the point seen.
glm::mat3 fundamental_matrix(const RingCamera& from, const RingCamera& to);
// How far, in pixels, `to_pixel` lies from the line on which `from_pixel` must land: a lower
// bound on how wrong a match is (an error along the line goes unseen).
float epipolar_distance(const glm::mat3& fundamental, const glm::vec2& from_pixel, const glm::vec2& to_pixel);

// A pixel of a photo of `size` pixels that was stored turned `quarter_turns` x 90 degrees
// counter-clockwise from the frame its calibration describes, in that calibrated frame.
// (templeRing's photos are stored upright at 480x640 and calibrated lying, at 640x480.)
glm::vec2 calibrated_pixel(const glm::vec2& stored, const glm::ivec2& size, int quarter_turns);

// The turn (0-3) under which `matches` (pixels of stored photos taken by `from` and `to`) lie
// closest to their epipolar lines, by median distance: photo sets do not say how their photos
// were turned after calibration, but a handful of right matches does.
int stored_quarter_turns(const RingCamera& from, const RingCamera& to, const std::vector<std::pair<glm::vec2, glm::vec2>>& matches,
                         const glm::ivec2& size);

// How many of `matches` (pixels of stored photos of `size`) lie more than `tolerance` pixels off
// their epipolar line (certainly wrong), under the stored turn the matches themselves point to.
struct EpipolarCheck {
  int off_line = 0;
  int quarter_turns = 0;
};
EpipolarCheck check_epipolar(const RingCamera& from, const RingCamera& to, const std::vector<std::pair<glm::vec2, glm::vec2>>& matches,
                             const glm::ivec2& size, float tolerance);

// Throws inkwire::Error with a one-line reason when there is no calibration file, a line is
// malformed, intrinsics are not a camera's, a rotation is not a rotation, or a named image is
// missing.
// `calibration`: the file to read; empty: the folder's own *_par.txt. The images it names are
// in `folder`.
PhotoRing load_photo_ring(const std::filesystem::path& folder, const std::filesystem::path& calibration = {});

// Three photos i, j, k in ring order whose neighbours are both at most `max_step_degrees` apart:
// the middle one can be synthesised from the outer two.
struct RingTriple {
  int before, middle, after;
  float t;  // where the middle view lies between the outer two (angle fraction)
};
std::vector<RingTriple> ring_triples(const PhotoRing& ring, float max_step_degrees = 12.0f);

}  // namespace inkwire
