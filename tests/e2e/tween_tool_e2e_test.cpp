// inkwire-tween as a user runs it (SPEC T8, T9): frames regenerated in a panning clip come out
// closer to what was there than holding or fading, and bad requests end with a reason.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../unit/test_images.hpp"
#include "e2e_support.hpp"

using namespace inkwire;
using namespace inkwire::e2e;

TEST(TweenToolE2ETest, RestoredFramesOfAPanBeatHoldingAndFadingAndBadRequestsAreRefused) {
  const fs::path dir = output_dir("tween-tool");
  fs::create_directories(dir / "clip");
  const int width = 200, height = 150, frames = 13, step = 3;
  const Image wide = test::random_discs(width + frames * step, height, 5);
  for (int f = 0; f < frames; ++f) save_image(test::panned(wide, f * step, width), dir / "clip" / (std::to_string(100 + f) + ".png"), false);
  Process restore("inkwire-tween", {"restore", "--input", (dir / "clip").string(), "--keep-every", "4", "--search", "24", "6",
                                    "--out", (dir / "restored-%04d.png").string(), "--json", (dir / "restore.json").string()},
                  dir / "restore.log");
  ASSERT_EQ(restore.wait(), 0) << restore.output();
  const nlohmann::json stats = nlohmann::json::parse(std::ifstream(dir / "restore.json"));
  EXPECT_EQ(stats["frames"], frames);
  EXPECT_EQ(stats["regenerated"], 9);  // all but frames 0, 4, 8 and 12
  EXPECT_EQ(stats["gaps"], 3);
  const auto& psnr = stats["psnr_against_input"];
  EXPECT_GT(psnr["tween"].get<double>(), psnr["crossfade"].get<double>() + 3.0) << stats.dump();
  EXPECT_GT(psnr["tween"].get<double>(), psnr["hold"].get<double>() + 3.0) << stats.dump();
  EXPECT_TRUE(fs::exists(dir / "restored-0012.png"));

  // A missing frame with nothing kept after it, and a malformed range: refused with a reason.
  Process at_end("inkwire-tween", {"restore", "--input", (dir / "clip").string(), "--missing", "12", "--out", (dir / "x.mp4").string()},
                 dir / "at-end.log");
  EXPECT_EQ(at_end.wait(), 1);
  EXPECT_NE(at_end.output().find("no kept frame on both sides"), std::string::npos) << at_end.output();
  Process malformed("inkwire-tween", {"restore", "--input", (dir / "clip").string(), "--missing", "5-x", "--out", (dir / "x.mp4").string()},
                    dir / "malformed.log");
  EXPECT_EQ(malformed.wait(), 1);
  EXPECT_NE(malformed.output().find("is not N or N-M"), std::string::npos) << malformed.output();
  Process no_face("inkwire-tween", {"morph", "--from", (dir / "clip" / "100.png").string(), "--to", (dir / "clip" / "104.png").string(),
                                    "--out", (dir / "m.mp4").string()},
                  dir / "no-face.log");
  EXPECT_EQ(no_face.wait(), 1);
  EXPECT_NE(no_face.output().find("give corresponding points with --points"), std::string::npos) << no_face.output();
}
