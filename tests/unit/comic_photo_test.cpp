// The comic look of a call's faces (client/render/face/comic_photo.cpp), which the browser's module
// runs too: flat areas stay flat and uninked, a gradient falls into exactly the asked bands, a
// strong edge is inked along its length and a faint one is not, alpha is kept.
#include <set>

#include <gtest/gtest.h>

#include "client/render/face/comic_photo.hpp"

using namespace inkwire;

namespace {

bool inked(const Image& image, int x, int y) {
  const uint8_t* p = image.at(x, y);
  return p[0] == 25 && p[1] == 20 && p[2] == 20;
}

}  // namespace

TEST(ComicPhotoTest, AFlatPhotoStaysOneUninkedTone) {
  Image image(64, 48, {140, 120, 100, 200});
  comic_photo(image);
  std::set<uint32_t> colours;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.at(x, y);
      colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
      ASSERT_EQ(p[3], 200) << "alpha changed at " << x << "," << y;
    }
  EXPECT_EQ(colours.size(), 1u);
  EXPECT_FALSE(inked(image, 32, 24));
}

TEST(ComicPhotoTest, AGentleGradientFallsIntoTheAskedBandsWithoutInk) {
  for (const int bands : {2, 4, 6}) {
    Image image(256, 32);
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        uint8_t* p = image.at(x, y);
        p[0] = p[1] = p[2] = uint8_t(x), p[3] = 255;
      }
    comic_photo(image, bands);
    std::set<int> tones;
    for (int x = 4; x < image.width - 4; ++x) {
      ASSERT_FALSE(inked(image, x, 16)) << "a gentle gradient was inked at " << x;
      tones.insert(image.at(x, 16)[1]);
    }
    EXPECT_EQ(int(tones.size()), bands) << bands << " bands asked";
  }
}

TEST(ComicPhotoTest, AStrongEdgeIsInkedAlongItsLengthAndAFaintOneIsNot) {
  Image image(96, 64, {40, 40, 40, 255});
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      uint8_t* p = image.at(x, y);
      if (x >= 48) p[0] = p[1] = p[2] = 220;  // a strong edge at x = 48
      if (y >= 40 && x < 48) p[0] = p[1] = p[2] = 46;  // a faint one at y = 40
    }
  comic_photo(image);
  int strong = 0;
  for (int y = 4; y < image.height - 4; ++y) {
    bool row = false;
    for (int x = 44; x <= 52; ++x) row |= inked(image, x, y);
    strong += row;
  }
  EXPECT_EQ(strong, image.height - 8) << "the strong edge is not inked along its whole length";
  int faint = 0;
  for (int x = 4; x < 40; ++x)
    for (int y = 36; y <= 44; ++y) faint += inked(image, x, y);
  EXPECT_EQ(faint, 0) << "a faint edge was inked";
  EXPECT_FALSE(inked(image, 20, 20));
  EXPECT_FALSE(inked(image, 75, 20));
}
