// inkwire-eval: quality figures on real data sets (CONTRACTS.md).
//   inkwire-eval tween-ring --dataset DIR --json OUT.json   (templeRing-style ring of photos)
#include <fstream>
#include <iostream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "eval_tween_ring.hpp"

using namespace inkwire;

int main(int argc, char** argv) {
  CLI::App app{"inkwire-eval: quality figures on real data sets"};
  app.require_subcommand(1);
  std::string json_path;
  eval::TweenRingOptions ring;
  CLI::App* tween_ring = app.add_subcommand("tween-ring", "synthesise each photo of a ring from its two neighbours; PSNR/SSIM of "
                                                          "nearest sample, cross-fade and tween against the real photo");
  tween_ring->add_option("--dataset", ring.dataset, "folder with the photos and a *_par.txt calibration")->required();
  tween_ring->add_option("--json", json_path, "write the figures here")->required();
  tween_ring->add_option("--limit", ring.limit, "at most this many triples (0: all)")->check(CLI::Range(0, 100000));
  tween_ring->add_option("--landmarks", ring.landmarks, "automatic landmarks per pair")->check(CLI::Range(3, 4000));
  tween_ring->add_option("--images", ring.images_dir, "write a truth | nearest | cross-fade | tween sheet per triple here");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    nlohmann::json out;
    if (tween_ring->parsed()) out = eval::run_tween_ring(ring);
    std::ofstream file(json_path);
    file << out.dump(2) << "\n";
    if (!file) throw Error("cannot write " + json_path);
    std::cout << out.dump(2) << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "inkwire-eval: " << e.what() << "\n";
    return 1;
  }
}
