#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/image.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::test;

TEST(ImageTest, PngRoundTripKeepsRowsTopDown) {
  Image img(4, 3, {0, 0, 0, 255});
  img.at(0, 0)[0] = 255;  // top-left red
  img.at(3, 2)[2] = 255;  // bottom-right blue
  const auto file = write_temp("roundtrip.png", "");
  save_image(img, file);
  const Image back = load_image(file);
  ASSERT_EQ(back.width, 4);
  ASSERT_EQ(back.height, 3);
  EXPECT_EQ(back.pixels, img.pixels);
}

TEST(ImageTest, FlipRowsReversesRowOrder) {
  Image img(2, 3);
  img.at(1, 0)[1] = 7;
  flip_rows(img);
  EXPECT_EQ(img.at(1, 2)[1], 7);
  EXPECT_EQ(img.at(1, 0)[1], 0);
}

TEST(ImageTest, TruncatedAndBogusFilesAreRefused) {
  Image img(64, 64, {10, 20, 30, 255});
  const auto good = write_temp("whole.png", "");
  save_image(img, good);
  std::ifstream in(good, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  EXPECT_THROW(load_image(write_temp("truncated.png", bytes.substr(0, bytes.size() / 2))), Error);
  EXPECT_THROW(load_image(write_temp("bogus.png", "not a png at all")), Error);
  EXPECT_THROW(load_image("/nonexistent.png"), Error);
}

TEST(ImageTest, CropsAndSideBySideKeepEveryPixelInPlace) {
  Image image(5, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 5; ++x) image.at(x, y)[0] = uint8_t(10 * y + x);
  const Image part = cropped(image, 1, 2, 3, 2);
  ASSERT_EQ(part.width, 3);
  ASSERT_EQ(part.height, 2);
  EXPECT_EQ(part.at(0, 0)[0], 21);
  EXPECT_EQ(part.at(2, 1)[0], 33);
  EXPECT_THROW(cropped(image, 3, 0, 3, 1), Error);
  EXPECT_THROW(cropped(image, -1, 0, 2, 1), Error);

  const Image both = side_by_side({part, cropped(image, 0, 0, 2, 2)});
  ASSERT_EQ(both.width, 5);
  EXPECT_EQ(both.at(2, 1)[0], 33);
  EXPECT_EQ(both.at(4, 1)[0], 11);
  EXPECT_THROW(side_by_side({part, image}), Error);
  EXPECT_THROW(side_by_side({}), Error);
}
