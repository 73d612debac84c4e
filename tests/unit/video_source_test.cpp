// Frames from outside (SPEC F1, P9): folders and patterns of images, bad sources refused.
#include <gtest/gtest.h>

#include <filesystem>

#include "common/error.hpp"
#include "common/video_source.hpp"
#include "test_data.hpp"

using namespace inkwire;

namespace {

std::filesystem::path write_sequence(const std::string& name, int frames) {
  const auto dir = test::scratch_dir() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  for (int i = 0; i < frames; ++i) {
    Image frame(32, 24, {uint8_t(i * 20), 100, 200, 255});
    char file[32];
    std::snprintf(file, sizeof file, "%04d.png", i);
    save_image(frame, dir / file);
  }
  return dir;
}

}  // namespace

TEST(VideoSourceTest, ReadsAFolderOfImagesInNameOrder) {
  const auto dir = write_sequence("folder", 5);
  std::filesystem::create_directories(dir / "not-an-image");
  VideoSource source(dir.string());
  for (int i = 0; i < 5; ++i) {
    const std::optional<Image> frame = source.next();
    ASSERT_TRUE(frame) << "frame " << i;
    EXPECT_EQ(frame->width, 32);
    EXPECT_EQ(frame->rgba(0, 0).r, uint8_t(i * 20));
  }
  EXPECT_FALSE(source.next()) << "the sequence ends";
}

TEST(VideoSourceTest, ReadsAPrintfPatternThroughOpenCV) {
  const auto dir = write_sequence("pattern", 3);
  VideoSource source((dir / "%04d.png").string());
  int n = 0;
  while (const std::optional<Image> frame = source.next()) {
    EXPECT_EQ(frame->height, 24);
    EXPECT_EQ(frame->rgba(1, 1).b, 200) << "colours arrive as RGB, not OpenCV's BGR";
    ++n;
  }
  EXPECT_EQ(n, 3);
}

TEST(VideoSourceTest, BadSourcesAreRefusedWithAReason) {
  EXPECT_THROW(VideoSource("/no/such/video.mp4"), Error);
  EXPECT_THROW(VideoSource("camera:x"), Error);
  EXPECT_THROW(VideoSource("camera:97"), Error) << "no such device here";
  const auto empty = test::scratch_dir() / "empty-folder";
  std::filesystem::create_directories(empty);
  EXPECT_THROW(VideoSource(empty.string()), Error);
  const auto junk = test::write_temp("junk.mp4", "this is not a video");
  try {
    VideoSource source(junk.string());
    EXPECT_FALSE(source.next()) << "a junk file yields no frames if OpenCV opens it at all";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("junk.mp4"), std::string::npos) << e.what();
  }
}
