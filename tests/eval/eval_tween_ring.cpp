#include "eval_tween_ring.hpp"

#include <chrono>
#include <cstdio>
#include <utility>

#include "client/gl/context.hpp"
#include "client/render/tween/pair_tween.hpp"
#include "common/error.hpp"
#include "common/image_metrics.hpp"
#include "server/tween/landmarks.hpp"
#include "server/tween/photo_ring.hpp"

namespace inkwire::eval {

constexpr float kWrongPixels = 3.0f;  // as for landmarks checked against a mesh

nlohmann::json run_tween_ring(const TweenRingOptions& o) {
  const PhotoRing ring = load_photo_ring(o.dataset);
  std::vector<RingTriple> triples = ring_triples(ring);
  if (triples.empty()) throw Error(o.dataset.string() + ": no three neighbouring photos close enough to tween");
  if (o.limit > 0 && int(triples.size()) > o.limit) triples.resize(size_t(o.limit));
  if (!o.images_dir.empty()) std::filesystem::create_directories(o.images_dir);

  const Image first = load_image(ring.folder / ring.names[0]);
  if (first.width > kMaxTweenImageSide || first.height > kMaxTweenImageSide)
    throw Error("ring photos are " + std::to_string(first.width) + "x" + std::to_string(first.height) + ", larger than tween data allows");
  auto context = create_offscreen_context(64, 64);
  LandmarkOptions landmark_options;
  landmark_options.count = o.landmarks;
  landmark_options.search = {64, 16};  // about 15 degrees of turn across a 480-pixel photo

  const char* methods[3] = {"nearest", "crossfade", "tween"};
  double psnr_sum[3] = {0, 0, 0}, ssim_sum[3] = {0, 0, 0}, seconds = 0.0, landmark_sum = 0.0, bytes_sum = 0.0, off_line_sum = 0.0;
  nlohmann::json per_triple = nlohmann::json::array();
  for (const RingTriple& tri : triples) {
    const Image before = load_image(ring.folder / ring.names[size_t(tri.before)]);
    const Image after = load_image(ring.folder / ring.names[size_t(tri.after)]);
    const Image truth = load_image(ring.folder / ring.names[size_t(tri.middle)]);
    for (const Image* image : {&before, &after, &truth})
      if (image->width != first.width || image->height != first.height) throw Error("ring photos differ in size");

    // What the server does once per pair: landmarks, tween data (through the codec, as a
    // client receives it).
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Landmark> landmarks = find_landmarks(grey_of(before), grey_of(after), landmark_options);
    TweenData data;
    data.width = first.width;
    data.height = first.height;
    data.directions = {ring.directions[size_t(tri.before)], ring.directions[size_t(tri.after)]};
    data.cells.push_back(cell_from_landmarks(landmarks, 0, 1));
    const std::vector<uint8_t> bytes = encode_tween(data);
    data = decode_tween(bytes);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // No exact correspondences on a real ring, but its calibration says where each landmark can
    // be: on its epipolar line. Landmarks farther off it are certainly wrong (a lower bound).
    // (templeRing's photos are stored turned from their calibration, those up to 31 one way and
    // those from 32 the other: the check finds the turn pair by pair.)
    std::vector<std::pair<glm::vec2, glm::vec2>> matches;
    for (const Landmark& l : landmarks) matches.push_back({l.source, l.target});
    const EpipolarCheck epipolar = check_epipolar(ring.cameras[size_t(tri.before)], ring.cameras[size_t(tri.after)], matches,
                                                  {first.width, first.height}, kWrongPixels);

    PairTween pair(before, after, data.cells[0]);
    const std::vector<Image> views = {tri.t < 0.5f ? before : after, pair.crossfade(tri.t), pair.tween(tri.t)};
    nlohmann::json row = {{"middle", ring.names[size_t(tri.middle)]}, {"t", tri.t}, {"landmarks", landmarks.size()},
                          {"off_epipolar", epipolar.off_line}, {"photo_quarter_turns", epipolar.quarter_turns},
                          {"bytes", bytes.size()}};
    for (int m = 0; m < 3; ++m) {
      const double p = psnr(views[size_t(m)], truth), s = ssim(views[size_t(m)], truth);
      psnr_sum[m] += p;
      ssim_sum[m] += s;
      row["psnr"][methods[m]] = p;
      row["ssim"][methods[m]] = s;
    }
    landmark_sum += double(landmarks.size());
    off_line_sum += double(epipolar.off_line);
    bytes_sum += double(bytes.size());
    per_triple.push_back(row);
    std::fprintf(stderr, "inkwire-eval: %s from its neighbours: %zu landmarks, PSNR nearest %.2f, cross-fade %.2f, tween %.2f dB\n",
                 ring.names[size_t(tri.middle)].c_str(), landmarks.size(), double(row["psnr"]["nearest"]),
                 double(row["psnr"]["crossfade"]), double(row["psnr"]["tween"]));
    if (!o.images_dir.empty())
      save_image(side_by_side({truth, views[0], views[1], views[2]}),
                 o.images_dir / (std::filesystem::path(ring.names[size_t(tri.middle)]).stem().string() + "-truth-nearest-crossfade-tween.png"),
                 false);
  }
  const double n = double(triples.size());
  nlohmann::json out = {{"pairs", triples.size()},
                        {"seconds_per_pair", seconds / n},
                        {"landmarks_per_pair", landmark_sum / n},
                        {"bytes_per_pair", bytes_sum / n},
                        {"wrong_fraction", nullptr},  // a real ring has no exact correspondences
                        {"off_epipolar_fraction", landmark_sum > 0.0 ? off_line_sum / landmark_sum : 0.0},
                        {"triples", per_triple}};
  for (int m = 0; m < 3; ++m) {
    out["psnr"][methods[m]] = psnr_sum[m] / n;
    out["ssim"][methods[m]] = ssim_sum[m] / n;
  }
  return out;
}

}  // namespace inkwire::eval
