// Photo rings in the Middlebury layout (SPEC T1b): a calibration file written here for four
// cameras round an object loads with the directions and cameras it describes; points seen by two
// of them satisfy their epipolar geometry (the check that bounds how wrong landmarks on real
// photos are); malformed calibration is refused with a one-line reason.
#include <cmath>
#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "common/image.hpp"
#include "server/products/photo_folder.hpp"
#include "server/tween/photo_ring.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::test;

namespace {

constexpr float kRadius = 0.6f;  // cameras' distance from the object, metres

// Camera `i` of four, 10 degrees apart round +Y at 20 degrees elevation, looking at the origin:
// rows of R are the camera's right, down and forward axes in world terms.
RingCamera ring_camera(int i) {
  const float az = glm::radians(10.0f * float(i)), el = glm::radians(20.0f);
  const glm::vec3 centre = kRadius * glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
  const glm::vec3 forward = glm::normalize(-centre);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  const glm::vec3 down = glm::cross(forward, right);
  RingCamera c;
  c.r = glm::transpose(glm::mat3(right, down, forward));
  c.t = -(c.r * centre);
  c.k = glm::transpose(glm::mat3(1500.0f, 0.0f, 300.0f, 0.0f, 1510.0f, 250.0f, 0.0f, 0.0f, 1.0f));
  return c;
}

glm::vec2 pixel_of(const RingCamera& c, const glm::vec3& x) {
  const glm::vec3 p = c.k * (c.r * x + c.t);
  return glm::vec2(p) / p.z;
}

// "name k11 .. k33 r11 .. r33 t1 t2 t3" for camera `i`, rows first, as the Middlebury files do.
std::string calibration_line(const std::string& name, const RingCamera& c) {
  std::ostringstream line;
  line.precision(9);
  line << name;
  for (const glm::mat3* m : {&c.k, &c.r})
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < 3; ++col) line << ' ' << (*m)[col][row];
  line << ' ' << c.t.x << ' ' << c.t.y << ' ' << c.t.z << '\n';
  return line.str();
}

// A ring folder with `lines` as its calibration (after the count) and an image file per name.
std::filesystem::path ring_folder(const std::string& name, int count, const std::string& lines) {
  const std::filesystem::path folder = test::scratch_dir() / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "ring_par.txt") << count << '\n' << lines;
  for (int i = 0; i < count; ++i) std::ofstream(folder / ("view" + std::to_string(i) + ".png"));
  return folder;
}

std::string four_cameras() {
  std::string lines;
  for (int i = 0; i < 4; ++i) lines += calibration_line("view" + std::to_string(i) + ".png", ring_camera(i));
  return lines;
}

}  // namespace

TEST(PhotoRingTest, CamerasAndDirectionsComeFromTheCalibration) {
  const PhotoRing ring = load_photo_ring(ring_folder("ring-ok", 4, four_cameras()));
  ASSERT_EQ(ring.names.size(), 4u);
  ASSERT_EQ(ring.cameras.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const RingCamera& c = ring_camera(i);
    const glm::vec3 centre = -(glm::transpose(c.r) * c.t);
    EXPECT_LT(glm::length(ring.directions[size_t(i)] - glm::normalize(centre)), 1e-4f) << i;
    EXPECT_LT(glm::length(ring.cameras[size_t(i)].t - c.t), 1e-5f) << i;
    EXPECT_NEAR(ring.cameras[size_t(i)].k[2][0], 300.0f, 1e-3f) << i;  // principal point x: row 1, column 3
  }
  EXPECT_EQ(ring_triples(ring).size(), 2u);  // 0-1-2 and 1-2-3
}

TEST(PhotoRingTest, MatchesLieOnTheirEpipolarLineAndMisplacedOnesDoNot) {
  const RingCamera a = ring_camera(0), b = ring_camera(2);
  const glm::mat3 f = fundamental_matrix(a, b);
  for (const glm::vec3& x : {glm::vec3(0.0f), glm::vec3(0.05f, -0.03f, 0.02f), glm::vec3(-0.04f, 0.06f, -0.05f)}) {
    const glm::vec2 p = pixel_of(a, x), q = pixel_of(b, x);
    EXPECT_LT(epipolar_distance(f, p, q), 0.01f);
    // Moved 5 pixels across its line, a match is 5 pixels off it; moved along, it is not.
    const glm::vec3 line = f * glm::vec3(p, 1.0f);
    const glm::vec2 across = glm::normalize(glm::vec2(line)), along(-across.y, across.x);
    EXPECT_NEAR(epipolar_distance(f, p, q + 5.0f * across), 5.0f, 0.01f);
    EXPECT_LT(epipolar_distance(f, p, q + 5.0f * along), 0.01f);
  }
  // Most of a 10-degree turn about a vertical axis is sideways: a match moved up or down by
  // 5 pixels from the truth is caught, whatever depth it sits at.
  const glm::vec2 p = pixel_of(a, glm::vec3(0.03f)), q = pixel_of(b, glm::vec3(0.03f));
  EXPECT_GT(epipolar_distance(f, p, q + glm::vec2(0.0f, 5.0f)), 4.0f);
}

TEST(PhotoRingTest, PhotosStoredTurnedFromTheirCalibrationAreFoundOut) {
  // Matches of points seen by cameras 0 and 2 (calibrated frame 600x500), as pixels of photos
  // stored turned a quarter counter-clockwise (500x600): the calibrated top row is the stored
  // left column, read upwards.
  const RingCamera a = ring_camera(0), b = ring_camera(2);
  const glm::ivec2 stored_size(500, 600);
  auto stored = [&](const glm::vec2& calibrated) { return glm::vec2(calibrated.y, float(stored_size.y - 1) - calibrated.x); };
  std::vector<std::pair<glm::vec2, glm::vec2>> upright, turned;
  for (int i = 0; i < 30; ++i) {
    const glm::vec3 x(0.01f * float(i % 7) - 0.03f, 0.013f * float(i % 5) - 0.02f, 0.011f * float(i % 3));
    upright.push_back({pixel_of(a, x), pixel_of(b, x)});
    turned.push_back({stored(pixel_of(a, x)), stored(pixel_of(b, x))});
  }
  EXPECT_EQ(stored_quarter_turns(a, b, upright, glm::ivec2(600, 500)), 0);
  ASSERT_EQ(stored_quarter_turns(a, b, turned, stored_size), 1);
  for (size_t i = 0; i < turned.size(); ++i) {  // back in the calibrated frame, where they were
    EXPECT_LT(glm::length(calibrated_pixel(turned[i].first, stored_size, 1) - upright[i].first), 1e-3f);
    EXPECT_LT(glm::length(calibrated_pixel(turned[i].second, stored_size, 1) - upright[i].second), 1e-3f);
  }
  // Three matches moved 6 stored pixels sideways (up or down in the calibrated frame, across
  // the mostly level lines of a turn about the vertical) are counted off their lines.
  for (size_t i : {3u, 11u, 20u}) turned[i].second.x += 6.0f;
  const EpipolarCheck check = check_epipolar(a, b, turned, stored_size, 3.0f);
  EXPECT_EQ(check.quarter_turns, 1);
  EXPECT_EQ(check.off_line, 3);
}

TEST(PhotoRingTest, MalformedCalibrationIsRefusedWithAReason) {
  const std::string good = calibration_line("view0.png", ring_camera(0)) + calibration_line("view1.png", ring_camera(1)) +
                           calibration_line("view2.png", ring_camera(2));
  EXPECT_EQ(error_of([&] { load_photo_ring(ring_folder("ring-good", 3, good)); }), "");

  RingCamera flat_k = ring_camera(2);
  flat_k.k[0][0] = 0.0f;  // no focal length
  const std::string bad_k = calibration_line("view0.png", ring_camera(0)) + calibration_line("view1.png", ring_camera(1)) +
                            calibration_line("view2.png", flat_k);
  EXPECT_NE(error_of([&] { load_photo_ring(ring_folder("ring-bad-k", 3, bad_k)); }).find("intrinsics"), std::string::npos);

  RingCamera squashed = ring_camera(2);
  squashed.r[0] *= 0.5f;
  const std::string bad_r = calibration_line("view0.png", ring_camera(0)) + calibration_line("view1.png", ring_camera(1)) +
                            calibration_line("view2.png", squashed);
  EXPECT_NE(error_of([&] { load_photo_ring(ring_folder("ring-bad-r", 3, bad_r)); }).find("not a rotation"), std::string::npos);

  std::string short_line = good.substr(0, good.rfind(' '));  // the last number cut off
  EXPECT_NE(error_of([&] { load_photo_ring(ring_folder("ring-short", 3, short_line)); }).find("not 21 numbers"), std::string::npos);

  const std::string escape = calibration_line("../view0.png", ring_camera(0)) + calibration_line("view1.png", ring_camera(1)) +
                             calibration_line("view2.png", ring_camera(2));
  EXPECT_NE(error_of([&] { load_photo_ring(ring_folder("ring-escape", 3, escape)); }).find("plain file name"), std::string::npos);
  EXPECT_NE(error_of([&] { load_photo_ring(ring_folder("ring-count", 4, good)); }).find("4 images announced"), std::string::npos);
}

TEST(PhotoRingTest, ACalibratedFolderIsTurnedInOrderOfAzimuthWhateverOrderItListsItsPhotosIn) {
  // Six cameras 10 degrees apart, listed as a lab shooting in two sweeps might: 0, 10, 40, 50,
  // then back for 20 and 30. Each photo a plain grey of its own shade, to follow it.
  const int listed[] = {0, 1, 4, 5, 2, 3};
  const std::filesystem::path folder = scratch_dir() / "ring-sweeps";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  std::string lines;
  for (int i : listed) {
    const std::string name = "view" + std::to_string(i) + ".png";
    lines += calibration_line(name, ring_camera(i));
    save_image(Image(60, 50, {uint8_t(40 * i), uint8_t(40 * i), uint8_t(40 * i), 255}), folder / name, false);
  }
  std::ofstream(folder / "ring_par.txt") << 6 << '\n' << lines;
  const PhotoFolder photos = read_photo_folder(folder, {});
  ASSERT_EQ(photos.names.size(), 6u);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(photos.names[size_t(i)], "view" + std::to_string(i) + ".png");
    EXPECT_EQ(photos.photos[size_t(i)].at(5, 5)[0], 40 * i) << "photo " << i << " is not its name's";
  }
  // Neighbouring photos 10 degrees apart, the pairs between them; half a turn is not closed.
  ASSERT_EQ(photos.cells.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(photos.cells[size_t(i)], (std::vector<uint16_t>{uint16_t(i), uint16_t(i + 1)}));
    const float step = glm::degrees(std::acos(std::clamp(glm::dot(photos.directions[size_t(i)], photos.directions[size_t(i + 1)]), -1.0f, 1.0f)));
    EXPECT_NEAR(step, 10.0f * std::cos(glm::radians(20.0f)), 0.2f) << i;
  }
}

// The camera a calibration describes, in the turntable's terms (the shape is carved under it and
// the camera found from the silhouettes is checked against it): the focal length at the photos'
// first level and the cameras' elevation above the ring's plane. The ring's axis is the normal of
// the plane the cameras' directions go round in, not the sum of their turns, which a ring covering
// one side tilts toward that side; up is the side the cameras look down from, whichever way the
// ring turned.
TEST(PhotoRingTest, ACalibratedRingsCameraIsItsFocalLengthAndElevationWhereverItsPhotosLie) {
  for (const bool reversed : {false, true}) {
    const std::filesystem::path folder = scratch_dir() / (reversed ? "ring-side-reversed" : "ring-side");
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    std::string lines;
    for (int i = 0; i < 6; ++i) {  // 0 to 50 degrees round: one side of the object
      const std::string name = "view" + std::to_string(i) + ".png";
      lines += calibration_line(name, ring_camera(reversed ? -i : i));
      save_image(Image(600, 500, {90, 90, 90, 255}), folder / name, false);  // the principal point (300, 250) in the middle
    }
    std::ofstream(folder / "ring_par.txt") << 6 << '\n' << lines;
    const PhotoFolder photos = read_photo_folder(folder, {});
    ASSERT_TRUE(photos.calibration.has_value());
    EXPECT_NEAR(photos.calibration->focal_px, 0.5f * (1500.0f + 1510.0f) * 512.0f / 600.0f, 0.01f) << "at the first level's 512 pixels";
    EXPECT_NEAR(photos.calibration->elevation_deg, 20.0f, 0.05f) << (reversed ? "turned the other way" : "");
    for (const glm::vec3& d : photos.directions) EXPECT_NEAR(glm::degrees(std::asin(d.y)), 20.0f, 0.05f);
    // A calibration in the folder is not read when the reader is told not to: the photos are then
    // a plain turn in file-name order, as inkwire-tween shape takes a folder without --calibration.
    const PhotoFolder plain = read_photo_folder(folder, {.folder_calibration = false});
    EXPECT_FALSE(plain.calibration.has_value());
    EXPECT_TRUE(plain.even_turn_assumed);
  }
}
