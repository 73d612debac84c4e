#pragma once
// `inkwire-eval tween-ring`: every photo of a real ring synthesised from its two neighbours by
// nearest sample, cross-fade and tween (automatic landmarks + warp), each compared with the
// real photo (PSNR, SSIM), and the share of landmarks off their epipolar line (certainly wrong).
// docs/cli.md fixes the JSON shape.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace inkwire::eval {

struct TweenRingOptions {
  std::filesystem::path dataset;
  int limit = 0;                    // 0: every triple
  int landmarks = 150;              // per pair
  std::filesystem::path images_dir; // when set, a comparison sheet per triple is written here
};

nlohmann::json run_tween_ring(const TweenRingOptions& options);

}  // namespace inkwire::eval
