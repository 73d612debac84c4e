// The person cut from a neutral photo's wall (common/face/person_matte.cpp), which the browser's
// module runs too: a drawn person (a face, hair above and beside it, a neck and a shirt) before a
// grainy wall is found whole and the wall is not, whatever the wall's colour; a face near the
// picture's edge, a tiny face and a photo of one colour are cut without a fault.
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/face/person_matte.hpp"
#include "synthetic_face.hpp"

using namespace inkwire;

namespace {

enum class Part { Wall, Face, Hair, Shirt };

// A person drawn around the synthetic face's landmarks, in its face frame (eye distance 1).
Part part_at(glm::vec2 f) {
  const auto in_ellipse = [&](glm::vec2 c, glm::vec2 r) { return ((f.x - c.x) / r.x) * ((f.x - c.x) / r.x) + ((f.y - c.y) / r.y) * ((f.y - c.y) / r.y) <= 1; };
  if (in_ellipse({0, 0.3f}, {1.08f, 1.35f})) return Part::Face;
  if (in_ellipse({0, -0.35f}, {1.3f, 1.3f}) && f.y < 0.6f) return Part::Hair;
  if (f.y > 1.3f && std::abs(f.x) < 0.55f) return Part::Face;  // the neck
  if (f.y > 2.3f && std::abs(f.x) < 0.8f + (f.y - 2.3f) * 1.5f) return Part::Shirt;
  return Part::Wall;
}

struct Drawn {
  Image photo;
  FaceLandmarks landmarks;
  std::vector<Part> parts;
};

Drawn drawn_person(glm::u8vec3 wall, glm::vec2 centre = {160, 130}, float eyes = 50) {
  Drawn d{Image(320, 320), test::synthetic_face({}, centre, eyes), {}};
  const FaceFrame frame = face_frame(d.landmarks);
  std::mt19937 random(7);
  std::uniform_int_distribution<int> grain(-12, 12);
  for (int y = 0; y < 320; ++y)
    for (int x = 0; x < 320; ++x) {
      const Part part = part_at(frame.to_face({x + 0.5f, y + 0.5f}));
      d.parts.push_back(part);
      const glm::u8vec3 c = part == Part::Face ? glm::u8vec3(222, 178, 150) : part == Part::Hair ? glm::u8vec3(70, 45, 30)
                          : part == Part::Shirt ? glm::u8vec3(40, 70, 170) : wall;
      uint8_t* p = d.photo.at(x, y);
      const int g = grain(random);
      for (int k = 0; k < 3; ++k) p[k] = uint8_t(std::clamp(int(c[k]) + g, 0, 255));
      p[3] = 255;
    }
  return d;
}

// The share of each part that the matte calls the person.
std::map<Part, double> kept(const Drawn& d, const PersonMatte& m) {
  std::map<Part, std::pair<double, double>> n;
  for (int y = 0; y < 320; ++y)
    for (int x = 0; x < 320; ++x) {
      auto& [in, all] = n[d.parts[size_t(y) * 320 + size_t(x)]];
      in += m.at(x, y) >= 128, all += 1;
    }
  std::map<Part, double> out;
  for (const auto& [part, c] : n) out[part] = c.first / c.second;
  return out;
}

}  // namespace

TEST(PersonMatteTest, ADrawnPersonIsFoundWholeAndTheWallIsNot) {
  // A pale wall, a wall as dark as the hair's neighbour, a saturated one.
  for (const glm::u8vec3 wall : {glm::u8vec3(200, 205, 210), glm::u8vec3(110, 120, 110), glm::u8vec3(60, 160, 90)}) {
    const Drawn d = drawn_person(wall);
    const PersonMatte m = person_matte(d.photo, d.landmarks);
    ASSERT_EQ(m.width, 320);
    ASSERT_EQ(m.height, 320);
    const auto share = kept(d, m);
    SCOPED_TRACE(testing::Message() << "wall " << int(wall.r) << "," << int(wall.g) << "," << int(wall.b));
    EXPECT_GT(share.at(Part::Face), 0.97);
    EXPECT_GT(share.at(Part::Hair), 0.9);
    EXPECT_GT(share.at(Part::Shirt), 0.85);
    EXPECT_LT(share.at(Part::Wall), 0.03);
  }
}

TEST(PersonMatteTest, TheCutIsSoftOnlyAtItsEdge) {
  const Drawn d = drawn_person({200, 205, 210});
  const PersonMatte m = person_matte(d.photo, d.landmarks);
  EXPECT_EQ(m.at(2, 2), 0);        // a corner: the wall
  EXPECT_EQ(m.at(160, 160), 255);  // the nose: the person
  size_t soft = 0;
  for (const uint8_t a : m.alpha) soft += a > 0 && a < 255;
  EXPECT_LT(double(soft) / double(m.alpha.size()), 0.05) << "a matte that is neither here nor there";
}

TEST(PersonMatteTest, LaidOnGroundTheWallIsTheGroundAndThePersonIsKept) {
  Drawn d = drawn_person({200, 205, 210});
  const PersonMatte m = person_matte(d.photo, d.landmarks);
  const glm::u8vec4 nose = d.photo.rgba(160, 160);
  lay_on_ground(d.photo, m, {246, 241, 231});
  EXPECT_EQ(d.photo.rgba(2, 2), glm::u8vec4(246, 241, 231, 255));
  EXPECT_EQ(d.photo.rgba(160, 160), nose);
}

TEST(PersonMatteTest, AwkwardPhotosAreCutWithoutAFault) {
  // The face at the picture's edge, half out; a face 4 pixels between the eyes; one colour.
  const Drawn edge = drawn_person({200, 205, 210}, {20, 40}, 50);
  const PersonMatte at_edge = person_matte(edge.photo, edge.landmarks);
  EXPECT_EQ(at_edge.at(20, 60), 255);
  const Drawn tiny = drawn_person({200, 205, 210}, {160, 130}, 4);
  EXPECT_NO_THROW(person_matte(tiny.photo, tiny.landmarks));
  const Image flat(64, 64, {128, 128, 128, 255});
  const PersonMatte one_colour = person_matte(flat, test::synthetic_face({}, {32, 28}, 12));
  EXPECT_EQ(one_colour.at(32, 34), 255);  // the face's hull is the person, whatever the colours say
  FaceLandmarks same_eyes{};
  EXPECT_THROW(person_matte(flat, same_eyes), Error);
}
