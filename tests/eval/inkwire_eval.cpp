// inkwire-eval: quality figures on real data sets (docs/cli.md).
//   inkwire-eval faces --dataset DIR --json OUT.json        (Yale-style subjectNN_label photos)
//   inkwire-eval face-templates --dataset DIR --subjects 01-08 --out TEMPLATES.json --json OUT.json
//   inkwire-eval tween-ring --dataset DIR --json OUT.json   (templeRing-style ring of photos)
#include <fstream>
#include <iostream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "eval_faces.hpp"
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
  eval::FacesOptions faces_options;
  CLI::App* faces = app.add_subcommand("faces", "expression selection on labelled faces (subjectNN_label.png; each subject's "
                                                "normal photo is its neutral calibration): per-label accuracy, confusion matrix");
  std::string templates_out;
  CLI::App* templates = app.add_subcommand("face-templates", "measure expression templates on labelled faces and write the "
                                                             "template file (development subjects only)");
  for (CLI::App* sub : {faces, templates}) {
    sub->add_option("--dataset", faces_options.dataset, "folder of subjectNN_label images")->required();
    sub->add_option("--json", json_path, "write the figures here")->required();
    sub->add_option("--subjects", faces_options.subjects, "which subjects, e.g. 01-08 (default: all)");
  }
  faces->add_option("--limit", faces_options.limit, "at most this many images (0: all)")->check(CLI::Range(0, 100000));
  faces->add_flag("--details", faces_options.details, "per-image features and choices in the JSON");
  templates->add_option("--out", templates_out, "template file to write")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    nlohmann::json out;
    if (tween_ring->parsed()) out = eval::run_tween_ring(ring);
    if (faces->parsed()) out = eval::run_faces(faces_options);
    if (templates->parsed()) out = eval::make_face_templates(faces_options, templates_out);
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
