// Suites "tween" and "landmarks" (SPEC T10, T7) at 256x256 on a textured product (landmarks
// also on assimp-testmodels' other textured objects, and on Spot when ../shared/data is there)
// rendered into a ring (and a sphere) of samples:
// fps of each synthesis method beside the default renderer drawing the mesh itself, tween bytes
// per pair, and automatic landmarks against the exact correspondences the mesh gives (seconds,
// wrong fraction, mean error).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <glm/geometric.hpp>
#include <opencv2/imgproc.hpp>

#include "bench_harness.hpp"
#include "client/render/styles.hpp"
#include "client/render/tween/mesh_samples.hpp"
#include "client/render/tween/tween_renderer.hpp"
#include "common/error.hpp"
#include "common/mesh_import.hpp"
#include "common/tween/view_sphere.hpp"
#include "server/tween/landmarks.hpp"
#include "server/tween/photo_ring.hpp"

namespace inkwire::bench {
namespace {

constexpr int kSize = 256;
constexpr float kDistance = 1.4f;  // bounding-box diagonals, as the tween style samples
constexpr float kWrongPixels = 3.0f;  // a landmark farther than this from the truth is wrong
const std::filesystem::path kAssimpModels = "/usr/share/assimp/models";
const std::filesystem::path kProduct = kAssimpModels / "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf";

// The packaged textured truck, else the largest object of the LOD series.
BenchObject product(Harness& harness) {
  BenchObject b;
  if (std::filesystem::exists(kProduct)) {
    b.name = "truck";
    b.object = load_scene_object(kProduct);
  } else {
    std::fprintf(stderr, "inkwire-bench: %s is missing (assimp-testmodels): using the LOD series\n", kProduct.c_str());
    b.name = harness.lod_series().back().name;
    b.object = harness.lod_series().back().object;
  }
  b.frame.viewport = {kSize, kSize};
  b.frame.camera = orbit_camera(b.object.topology.bounds, 7.5f, 0.0f, kDistance);
  b.frame.light_direction = default_light_direction(b.frame.camera);
  return b;
}

// The pinhole camera of a square sample (pixels, y down, looking along +z) from a GL camera
// (y up, looking along -z): the same geometry the photo rings' calibration gives.
RingCamera pixel_camera(const Camera& camera, int size) {
  const glm::mat4 projection = camera.projection(1.0f), view = camera.view();
  const float half = 0.5f * float(size);
  RingCamera c;
  c.k = glm::transpose(glm::mat3(projection[0][0] * half, 0.0f, half, 0.0f, projection[1][1] * half, half, 0.0f, 0.0f, 1.0f));
  const glm::mat3 flip(1.0f, 0.0f, 0.0f, 0.0f, -1.0f, 0.0f, 0.0f, 0.0f, -1.0f);
  c.r = flip * glm::mat3(view);
  c.t = flip * glm::vec3(view[3]);
  return c;
}

}  // namespace

std::vector<Result> run_tween_suite(Harness& harness) {
  const int frames = harness.options().frames;
  BenchObject object = product(harness);
  Canvas canvas(kSize, kSize, 1);
  std::vector<Result> results;
  double default_fps = 0.0;
  struct Variant {
    const char* name;
    std::vector<std::string> settings;
  };
  const std::vector<Variant> variants = {
      {"", {}},
      {"nearest", {"method=nearest"}},
      {"crossfade", {"method=crossfade"}},
      {"linear", {"method=linear"}},
      {"bilinear", {"method=bilinear"}},
      {"trilinear", {"method=trilinear"}},
      // The study's way: one pass per sample into an off-screen view, then laid over the frame.
      {"crossfade-per-sample", {"method=crossfade", "passes=per-sample"}},
      {"bilinear-layered", {"method=bilinear", "passes=per-sample", "overlap=layered"}},
      {"bilinear-depthclear", {"method=bilinear", "passes=per-sample", "overlap=depth-clear"}},
      {"trilinear-per-sample", {"method=trilinear", "passes=per-sample"}},
  };
  for (const Variant& v : variants) {
    const bool reference = *v.name == '\0';
    auto renderer = reference ? make_renderer("default") : make_renderer("tween", v.settings);
    renderer->prepare(object.object);
    Result r = harness.time_frames(*renderer, object, frames, &canvas);
    r.suite = "tween";
    r.renderer = reference ? "default" : "tween";
    r.variant = v.name;
    if (reference) default_fps = r.fps_median;
    r.rel_default = r.fps_median / default_fps;
    for (const auto& [key, value] : renderer->counters()) r.counters[key] = value;
    if (!reference) {
      r.counters["bytes_per_pair"] = r.counters["bytes_per_cell"];
      r.counters.erase("bytes_per_cell");
      r.counters.erase("cell");
    }
    results.push_back(std::move(r));
    std::fprintf(stderr, "inkwire-bench: tween %s done\n", reference ? "default" : v.name);
  }
  return results;
}

namespace {

// Automatic landmarks between every pair of neighbours of a 24-sample ring rendered from
// `object`, checked against the exact correspondence its mesh gives.
Result measure_landmark_ring(const SceneObject& object, const std::string& name) {
  const int samples = 24;
  const MeshSamples set = render_mesh_samples(object, ring_directions(samples), kSize, kDistance);
  LandmarkOptions options;  // 65 landmarks, the study's count
  std::vector<double> seconds;
  double error_sum = 0.0;
  int found = 0, checked = 0, wrong = 0, unverifiable = 0, hidden = 0, wrong_position = 0, beside_occluder = 0, off_line = 0;
  std::map<std::string, double> rejected;  // per pair, by rule
  for (int i = 0; i < samples; ++i) {
    const int j = (i + 1) % samples;
    const cv::Mat a = grey_of(set.images[size_t(i)]), b = grey_of(set.images[size_t(j)]);
    const auto start = std::chrono::steady_clock::now();
    LandmarkStats stats;
    const std::vector<Landmark> landmarks = find_landmarks(a, b, options, &stats);
    for (const auto& [rule, count] : std::initializer_list<std::pair<const char*, int>>{
             {"candidates", stats.candidates}, {"rejected_border", stats.near_border}, {"rejected_spacing", stats.too_close},
             {"rejected_weak", stats.weak}, {"rejected_self_similar", stats.not_distinctive}, {"rejected_no_match", stats.no_match},
             {"rejected_not_unique", stats.not_unique}, {"rejected_not_found_back", stats.not_found_back},
             {"rejected_inconsistent", stats.inconsistent}})
      rejected[rule] += double(count) / samples;
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    // What the epipolar check of the real photos would catch here (pixel centres at +0.5).
    const glm::mat3 f = fundamental_matrix(pixel_camera(set.cameras[size_t(i)], kSize), pixel_camera(set.cameras[size_t(j)], kSize));
    for (const Landmark& l : landmarks) {
      ++found;
      off_line += epipolar_distance(f, l.source + 0.5f, l.target + 0.5f) > kWrongPixels;
      // The truth: the surface under the landmark, projected into the other sample. A landmark
      // on the background side of the outline has no surface point: it cannot be checked.
      const std::optional<glm::vec3> point = set.surface_point(i, l.source);
      if (!point) {
        ++unverifiable;
        continue;
      }
      ++checked;
      const auto truth = set.seen_position(j, *point);
      const float error = truth ? glm::length(*truth - l.target) : 1e9f;
      // Where the surface point projects whether or not the other sample shows it.
      const glm::vec2 projected(set.project(j, *point));
      hidden += !truth;
      wrong_position += glm::length(projected - l.target) > kWrongPixels;
      // Seen, but a nearer surface lies within a pixel: corners where one part passes in front
      // of another (the cautious test that picks exact control points refuses these).
      beside_occluder += truth && !set.visible_position(j, *point);
      if (error > kWrongPixels) {
        ++wrong;
      } else {
        error_sum += error;
      }
    }
  }
  std::sort(seconds.begin(), seconds.end());
  Result r;
  r.suite = "landmarks";
  r.renderer = "landmarks";
  r.variant = "ring24,256x256";
  r.object = name;
  r.faces = object.mesh.face_count();
  r.frames = samples;
  r.counters["landmarks"] = double(found) / samples;
  r.counters["seconds"] = seconds[seconds.size() / 2];
  r.counters["wrong_fraction"] = checked ? double(wrong) / checked : 0.0;
  r.counters["hidden_fraction"] = checked ? double(hidden) / checked : 0.0;
  r.counters["wrong_position_fraction"] = checked ? double(wrong_position) / checked : 0.0;
  r.counters["beside_occluder_fraction"] = checked ? double(beside_occluder) / checked : 0.0;
  r.counters["off_epipolar_fraction"] = found ? double(off_line) / found : 0.0;
  r.counters["mean_error_px"] = checked > wrong ? error_sum / double(checked - wrong) : 0.0;
  r.counters["unverifiable_fraction"] = found ? double(unverifiable) / found : 0.0;
  r.counters.insert(rejected.begin(), rejected.end());
  return r;
}

// Spot, the textured cow of ../shared/data (an OBJ whose texture sits beside it, no material
// file), when present: a second textured object, a smooth animal with painted patches.
std::optional<SceneObject> spot() {
  const std::filesystem::path dir = std::filesystem::path(INKWIRE_SHARED_DATA_DIR) / "spot";
  if (!std::filesystem::exists(dir / "spot_triangulated.obj") || !std::filesystem::exists(dir / "spot_texture.png")) {
    std::fprintf(stderr, "inkwire-bench: %s is absent: skipping the landmarks row on Spot\n", dir.c_str());
    return std::nullopt;
  }
  Mesh mesh = load_mesh(dir / "spot_triangulated.obj");
  if (mesh.materials.size() != 1 || !mesh.has_uvs()) throw Error("spot: expected one material and texture coordinates");
  mesh.materials[0].texture_file = dir / "spot_texture.png";
  normalise(mesh, 10.0f);
  return make_scene_object(std::move(mesh));
}

}  // namespace

std::vector<Result> run_landmarks_suite(Harness& harness) {
  BenchObject object = product(harness);
  std::vector<Result> results = {measure_landmark_ring(object.object, object.name)};
  if (const std::optional<SceneObject> cow = spot()) results.push_back(measure_landmark_ring(*cow, "spot"));
  // The other textured objects assimp-testmodels carries, so that the rules are judged on more
  // than the object they were measured on: painted camouflage on a jeep with a roll bar, a
  // spider whose thin legs cross in front of one another, a character in a T-pose, and a globe
  // whose painted grid of 15-degree cells turns in step with the ring.
  for (const auto& [name, file] : std::initializer_list<std::pair<const char*, const char*>>{
           {"jeep", "MS3D/jeep1.ms3d"}, {"spider", "OBJ/spider.obj"}, {"mrfixit", "IQM/mrfixit.iqm"}, {"earth", "Collada/earthCylindrical.DAE"}}) {
    const std::filesystem::path path = kAssimpModels / file;
    if (!std::filesystem::exists(path)) {
      std::fprintf(stderr, "inkwire-bench: %s is missing (assimp-testmodels): skipping its landmarks row\n", path.c_str());
      continue;
    }
    results.push_back(measure_landmark_ring(load_scene_object(path), name));
  }

  // Real photos (richer texture than any packaged model), when ../shared/data is beside the
  // checkout: two ring neighbours 15 degrees apart, the centre square scaled to 256x256. No
  // exact correspondences exist; the calibration gives a lower bound on the wrong ones: the
  // landmarks off their epipolar line.
  const std::filesystem::path folder = std::filesystem::path(INKWIRE_SHARED_DATA_DIR) / "templeRing";
  if (!std::filesystem::exists(folder / "templeR0002.png")) {
    std::fprintf(stderr, "inkwire-bench: %s is absent: skipping the landmarks-on-photos row\n", folder.c_str());
    return results;
  }
  const PhotoRing ring = load_photo_ring(folder);
  const int first = 1, second = 3;  // templeR0002 and templeR0004
  const cv::Mat photo_a = grey_of(load_image(folder / ring.names[size_t(first)]));
  const cv::Mat photo_b = grey_of(load_image(folder / ring.names[size_t(second)]));
  const glm::ivec2 photo_size(photo_a.cols, photo_a.rows);
  const int side = std::min(photo_a.cols, photo_a.rows);
  const glm::vec2 corner(float(photo_a.cols - side) / 2.0f, float(photo_a.rows - side) / 2.0f);
  const float scale = float(side) / float(kSize);  // photo pixels per pixel of the square
  auto square = [&](const cv::Mat& grey) {
    cv::Mat out;
    cv::resize(grey(cv::Rect(int(corner.x), int(corner.y), side, side)), out, cv::Size(kSize, kSize), 0, 0, cv::INTER_AREA);
    return out;
  };
  const cv::Mat a = square(photo_a), b = square(photo_b);
  std::vector<double> photo_seconds;
  std::vector<Landmark> landmarks;
  for (int repeat = 0; repeat < 5; ++repeat) {
    const auto start = std::chrono::steady_clock::now();
    landmarks = find_landmarks(a, b, LandmarkOptions{});
    photo_seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(photo_seconds.begin(), photo_seconds.end());
  // Back in the photos' pixels (pixel centres: the square's pixel centre x lies at x + 0.5).
  std::vector<std::pair<glm::vec2, glm::vec2>> matches;
  auto in_photo = [&](const glm::vec2& p) { return corner + (p + 0.5f) * scale - 0.5f; };
  for (const Landmark& l : landmarks) matches.push_back({in_photo(l.source), in_photo(l.target)});
  const EpipolarCheck epipolar = check_epipolar(ring.cameras[size_t(first)], ring.cameras[size_t(second)], matches, photo_size, kWrongPixels * scale);
  Result row;
  row.suite = "landmarks";
  row.renderer = "landmarks";
  row.variant = "templeRing 2->4,256x256";
  row.object = "temple";
  row.frames = 5;
  row.counters["landmarks"] = double(landmarks.size());
  row.counters["seconds"] = photo_seconds[photo_seconds.size() / 2];
  row.counters["off_epipolar_fraction"] = landmarks.empty() ? 0.0 : double(epipolar.off_line) / double(landmarks.size());
  results.push_back(row);
  return results;
}

}  // namespace inkwire::bench
