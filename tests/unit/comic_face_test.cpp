// A call member's photo drawn as a comic face (client/render/face/comic_face.cpp), which the
// browser's module runs too: the wall becomes the ground and alpha is kept, the features are inked
// along their landmarks and the cheek is not, dark eye sockets are not drawn as blots, a gradient
// falls into at most three tones, and the person's outline is inked.
#include <set>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "client/render/face/comic_face.hpp"
#include "common/luminance.hpp"
#include "synthetic_face.hpp"

using namespace inkwire;

namespace {

constexpr glm::u8vec3 kGround{246, 241, 231};

struct Sitter {
  Image photo;
  FaceLandmarks landmarks = test::synthetic_face({}, {160, 130}, 50);
  FaceFrame frame = face_frame(landmarks);
  PersonMatte matte;

  // A grey photo whose light is `light` at each face-frame point; the person an ellipse about the
  // head (eye distance 1, y down).
  template <typename Light>
  explicit Sitter(Light light) : photo(320, 320), matte{320, 320, std::vector<uint8_t>(320 * 320)} {
    for (int y = 0; y < 320; ++y)
      for (int x = 0; x < 320; ++x) {
        const glm::vec2 f = frame.to_face({x + 0.5f, y + 0.5f});
        uint8_t* p = photo.at(x, y);
        p[0] = p[1] = p[2] = uint8_t(light(f)), p[3] = 200;
        const bool person = (f.x / 1.4f) * (f.x / 1.4f) + ((f.y - 0.3f) / 1.9f) * ((f.y - 0.3f) / 1.9f) <= 1;
        matte.alpha[size_t(y) * 320 + size_t(x)] = person ? 255 : 0;
      }
  }
  glm::ivec2 pixel(glm::vec2 face_point) const { return glm::ivec2(frame.to_image(face_point)); }
  float light_at(glm::vec2 face_point) const {
    const glm::ivec2 p = pixel(face_point);
    const uint8_t* c = photo.at(p.x, p.y);
    return rec601_luma<float>(c[0], c[1], c[2]);
  }
};

}  // namespace

TEST(ComicFaceTest, TheWallBecomesTheGroundAndAlphaIsKept) {
  Sitter s([](glm::vec2) { return 150.0f; });
  comic_face(s.photo, s.landmarks, s.matte, kGround);
  for (int y = 0; y < 320; ++y)
    for (int x = 0; x < 320; ++x) {
      const glm::u8vec4 c = s.photo.rgba(x, y);
      ASSERT_EQ(c.a, 200) << "alpha changed at " << x << "," << y;
      if (s.matte.at(x, y) == 0) ASSERT_EQ(glm::u8vec3(c), kGround) << "the wall is not the ground at " << x << "," << y;
    }
}

TEST(ComicFaceTest, TheFeaturesAreInkedAlongTheirLandmarksAndTheCheekIsNot) {
  Sitter s([](glm::vec2) { return 190.0f; });
  comic_face(s.photo, s.landmarks, s.matte, kGround);
  const auto dark = [&](glm::vec2 p) {
    const uint8_t* c = s.photo.at(int(p.x), int(p.y));
    return rec601_luma<float>(c[0], c[1], c[2]) < 70;
  };
  using namespace face_index;
  EXPECT_TRUE(dark(s.landmarks[19])) << "the left brow";
  EXPECT_TRUE(dark(s.landmarks[24])) << "the right brow";
  EXPECT_TRUE(dark((s.landmarks[37] + s.landmarks[38]) / 2.0f)) << "the left upper lid";
  EXPECT_TRUE(dark((s.landmarks[43] + s.landmarks[44]) / 2.0f)) << "the right upper lid";
  EXPECT_TRUE(dark(s.landmarks[33])) << "the nose's base";
  EXPECT_TRUE(dark(s.landmarks[62])) << "between the lips";
  EXPECT_TRUE(dark(s.landmarks[kChin] - glm::vec2(0, 1))) << "the chin";
  EXPECT_GT(s.light_at({-0.7f, 0.6f}), 150) << "the cheek was inked";
  EXPECT_GT(s.light_at({0.0f, -0.9f}), 150) << "the forehead was inked";
}

TEST(ComicFaceTest, DarkEyeSocketsAreNotDrawnAsBlots) {
  // Light from above leaves the sockets almost black in a photo; a cartoonist shades them.
  Sitter s([](glm::vec2 f) {
    const bool socket = glm::distance(f, {-0.5f, -0.1f}) < 0.3f || glm::distance(f, {0.5f, -0.1f}) < 0.3f;
    return socket ? 15.0f : 200.0f;
  });
  comic_face(s.photo, s.landmarks, s.matte, kGround);
  EXPECT_GE(s.light_at({-0.5f, -0.24f}), 45) << "the left socket is a blot";
  EXPECT_GE(s.light_at({0.5f, -0.24f}), 45) << "the right socket is a blot";
}

TEST(ComicFaceTest, AGradientFallsIntoAtMostThreeTones) {
  Sitter s([](glm::vec2 f) { return std::clamp(130.0f + 70.0f * f.x, 20.0f, 240.0f); });
  comic_face(s.photo, s.landmarks, s.matte, kGround);
  std::set<int> tones;
  for (float x = -0.9f; x <= 0.9f; x += 0.02f) tones.insert(int(std::lround(s.light_at({x, -0.9f}))));
  EXPECT_LE(tones.size(), 3u);
  EXPECT_GE(tones.size(), 2u) << "a gradient over the whole face drawn in one tone";
}

TEST(ComicFaceTest, ThePersonsOutlineIsInked) {
  Sitter s([](glm::vec2) { return 190.0f; });
  comic_face(s.photo, s.landmarks, s.matte, kGround);
  int inked = 0, edge = 0;
  for (int y = 1; y + 1 < 320; ++y)
    for (int x = 1; x + 1 < 320; ++x) {
      if (s.matte.at(x, y) == 0 || s.matte.at(x - 1, y) != 0) continue;  // the person's first pixel from the left
      ++edge;
      const uint8_t* c = s.photo.at(x, y);
      inked += rec601_luma<float>(c[0], c[1], c[2]) < 50;
    }
  ASSERT_GT(edge, 100);
  EXPECT_EQ(inked, edge);
}
