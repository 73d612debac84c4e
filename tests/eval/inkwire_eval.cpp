// inkwire-eval: quality figures on real data sets (docs/cli.md).
//   inkwire-eval faces --dataset DIR --json OUT.json        (Yale-style subjectNN_label photos)
//   inkwire-eval face-templates --dataset DIR --subjects 01-08 --out TEMPLATES.json --json OUT.json
//   inkwire-eval tween-ring --dataset DIR --json OUT.json   (templeRing-style ring of photos)
//   inkwire-eval face-pose [--clip VIDEO] [--yale DIR] --json OUT.json [--images DIR]  (faces drawn with their head's pose)
//   inkwire-eval head-pose --neutral PHOTO --image PICTURE --json OUT.json  (the pose a picture shows, as a call reads it)
#include <fstream>
#include <iostream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "eval_face_pose.hpp"
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
  eval::FacePoseOptions pose_options;
  CLI::App* pose = app.add_subcommand("face-pose", "faces drawn from what a call sends against the faces that were there: head pose "
                                                   "error, NME and the turn's reading, before poses travelled and now");
  pose->add_option("--clip", pose_options.clip, "a video with turning heads (e.g. /usr/share/doc/opencv-doc/examples/data/Megamind.avi)");
  pose->add_option("--yale", pose_options.yale, "a folder of subjectNN_normal photos, turned in the picture for roll");
  pose->add_option("--json", json_path, "write the figures here")->required();
  pose->add_option("--images", pose_options.images_dir, "write sender | before | now sheets of some frames here");
  pose->add_option("--limit", pose_options.limit, "at most this many frames of the clip (0: all)")->check(CLI::Range(0, 1000000));
  std::string neutral_photo, posed_picture;
  CLI::App* head = app.add_subcommand("head-pose", "the head's pose in a picture against a neutral photo of the same face, read as a "
                                                   "call's server reads a member's camera (yaw, pitch, roll in degrees)");
  head->add_option("--neutral", neutral_photo, "the neutral photo")->required();
  head->add_option("--image", posed_picture, "the picture to read")->required();
  head->add_option("--json", json_path, "write the pose here")->required();
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
    if (pose->parsed()) out = eval::run_face_pose(pose_options);
    if (head->parsed()) out = eval::read_head_pose(neutral_photo, posed_picture);
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
