// Tween data (SPEC T3, T6): the codec round-trips exactly to its quantisation and refuses
// truncated, oversized, malformed and random input; 65 points per pair fit in 500 bytes; paths,
// view location, the Delaunay warp mesh and the spreading of exact points behave.
#include <cmath>
#include <cstdio>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/random.hpp"
#include "common/tween/point_spread.hpp"
#include "common/tween/tween_data.hpp"
#include "common/tween/view_sphere.hpp"
#include "common/tween/warp_mesh.hpp"
#include "test_data.hpp"

using namespace inkwire;

namespace {

// A ring of `samples` samples whose pairs carry `points` control points moving as on a
// turntable: x shifts by up to `shift` pixels, y barely, the halfway point bends off the chord.
TweenData turntable_like(int samples, int points, float shift, uint64_t seed, int size = 256) {
  Random random(seed);
  TweenData d;
  d.width = d.height = size;
  d.directions = ring_directions(samples);
  for (const auto& cell : ring_cells(samples)) {
    TweenCell c;
    c.samples = cell;
    for (int i = 0; i < points; ++i) {
      const glm::vec2 a(random.uniform(30.0f, size - 30.0f), random.uniform(30.0f, size - 30.0f));
      const glm::vec2 b = a + glm::vec2(random.uniform(-shift, shift), random.uniform(-1.5f, 1.5f));
      const glm::vec2 mid = (a + b) * 0.5f + glm::vec2(random.uniform(-0.8f, 0.8f), random.uniform(-0.3f, 0.3f));
      c.points.push_back({a, mid, b});
    }
    d.cells.push_back(std::move(c));
  }
  return d;
}

std::string error_of(const std::vector<uint8_t>& bytes) {
  return test::error_of([&] { decode_tween(bytes); });
}

}  // namespace

TEST(TweenDataTest, RoundTripsExactlyToItsQuantisation) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const TweenData d = turntable_like(24, 65, 25.0f, seed);
    const TweenData back = decode_tween(encode_tween(d));
    EXPECT_EQ(back, quantised(d)) << "seed " << seed;
    // Quantisation is 1/16 pixel: no coordinate moves more than half of that.
    for (size_t c = 0; c < d.cells.size(); ++c)
      for (size_t i = 0; i < d.cells[c].points.size(); ++i)
        for (int k = 0; k < 3; ++k) {
          EXPECT_LE(std::abs(back.cells[c].points[i][k].x - d.cells[c].points[i][k].x), 1.0f / 32.0f);
          EXPECT_LE(std::abs(back.cells[c].points[i][k].y - d.cells[c].points[i][k].y), 1.0f / 32.0f);
        }
  }
}

TEST(TweenDataTest, TrianglesOfASphereRoundTripToo) {
  const ViewSphere sphere = geodesic_sphere(1);
  TweenData d;
  d.width = 320;
  d.height = 240;
  d.directions = sphere.directions;
  Random random(11);
  for (const auto& t : sphere.triangles) {
    TweenCell c;
    c.samples = t;
    for (int i = 0; i < 30; ++i) {
      const glm::vec2 a(random.uniform(0.0f, 320.0f), random.uniform(0.0f, 240.0f));
      c.points.push_back({a, a + glm::vec2(random.uniform(-9.0f, 9.0f), random.uniform(-9.0f, 9.0f)),
                          a + glm::vec2(random.uniform(-9.0f, 9.0f), random.uniform(-9.0f, 9.0f))});
      for (glm::vec2& p : c.points.back()) p = glm::clamp(p, glm::vec2(0.0f), glm::vec2(320.0f, 240.0f));
    }
    d.cells.push_back(std::move(c));
  }
  EXPECT_EQ(decode_tween(encode_tween(d)), quantised(d));
}

TEST(TweenDataTest, SixtyFivePointsPerPairFitInFiveHundredBytes) {
  // 25 pixels of sideways motion per pair is a 15-degree step of an object filling a 256-pixel
  // sample; the study stored 12 bytes per point (780 bytes for 65).
  const TweenData d = turntable_like(24, 65, 25.0f, 5);
  const double per_pair = double(encode_tween(d).size()) / double(d.cells.size());
  std::printf("bytes per pair: %.1f\n", per_pair);
  EXPECT_LE(per_pair, 500.0);
}

TEST(TweenDataTest, RefusesEveryTruncation) {
  const std::vector<uint8_t> bytes = encode_tween(turntable_like(4, 20, 10.0f, 9));
  for (size_t n = 0; n < bytes.size(); ++n) {
    const std::string e = error_of(std::vector<uint8_t>(bytes.begin(), bytes.begin() + long(n)));
    EXPECT_FALSE(e.empty()) << "a prefix of " << n << " bytes decoded";
  }
}

TEST(TweenDataTest, RefusesMalformedInputWithAReason) {
  const std::vector<uint8_t> good = encode_tween(turntable_like(4, 20, 10.0f, 9));
  auto with = [&](size_t at, uint8_t value) {
    std::vector<uint8_t> b = good;
    b[at] = value;
    return error_of(b);
  };
  EXPECT_NE(with(0, 'X').find("magic"), std::string::npos);
  EXPECT_NE(with(4, 9).find("version 9"), std::string::npos);
  EXPECT_NE(with(7, 0x20).find("image size"), std::string::npos);  // width 8192 + ...
  std::vector<uint8_t> trailing = good;
  trailing.push_back(0);
  EXPECT_NE(error_of(trailing).find("after the last cell"), std::string::npos);
  std::vector<uint8_t> huge(kMaxTweenBytes + 1, 0);
  EXPECT_NE(error_of(huge).find("over the limit"), std::string::npos);
  // A cell naming a sample that does not exist (first cell's first index, after the header and
  // the 4 x 6 bytes of directions, and its arity byte).
  const size_t first_index = 14 + 4 * 6 + 1;
  EXPECT_NE(with(first_index, 77).find("out of range"), std::string::npos);
}

TEST(TweenDataTest, RandomBytesNeverCrashAndMostlyFail) {
  Random random(1234);
  int decoded = 0;
  for (int i = 0; i < 20000; ++i) {
    std::vector<uint8_t> b(size_t(random.uniform(0.0f, 300.0f)));
    for (uint8_t& x : b) x = uint8_t(random.uniform(0.0f, 256.0f));
    if (i % 2) {  // half of them with a valid header, to get past the magic
      const std::vector<uint8_t> head = {'I', 'K', 'T', 'W', 1, 0};
      for (size_t k = 0; k < head.size() && k < b.size(); ++k) b[k] = head[k];
    }
    decoded += error_of(b).empty();
  }
  EXPECT_LT(decoded, 200);
}

TEST(TweenDataTest, PathsPassThroughTheirThreePositions) {
  const ControlPoint p{glm::vec2(0, 0), glm::vec2(6, 3), glm::vec2(10, 0)};
  EXPECT_EQ(path_position(p, 0.0f), p[0]);
  EXPECT_EQ(path_position(p, 0.5f), p[1]);
  EXPECT_EQ(path_position(p, 1.0f), p[2]);
  const glm::vec3 w = path_weights(0.3f);
  EXPECT_NEAR(w.x + w.y + w.z, 1.0f, 1e-6f);
}

TEST(TweenDataTest, ViewsFindTheirRingPairAndSphereTriangle) {
  TweenData ring;
  ring.width = ring.height = 64;
  ring.directions = ring_directions(24);
  for (const auto& c : ring_cells(24)) ring.cells.push_back({c, {}});
  // 37.5 degrees: halfway between samples 2 (30) and 3 (45), even from 20 degrees above.
  for (float el : {0.0f, 20.0f}) {
    const glm::vec3 view = ring_directions(48, el)[5];  // every 7.5 degrees: the 5th is 37.5
    const CellLocation at = locate_view(ring, view);
    ASSERT_EQ(at.cell, 2);
    EXPECT_NEAR(at.t, 0.5f, 1e-4f);
    EXPECT_TRUE(at.inside);
  }
  // Half a ring (photos 0..12, no pair closing it): a view from behind is past its end.
  TweenData half = ring;
  half.cells.resize(12);
  EXPECT_TRUE(locate_view(half, ring_directions(24)[7]).inside);
  const CellLocation behind = locate_view(half, ring_directions(24)[18]);
  EXPECT_FALSE(behind.inside);
  EXPECT_TRUE(behind.t == 0.0f || behind.t == 1.0f);
  const ViewSphere sphere = geodesic_sphere(1);
  TweenData s;
  s.width = s.height = 64;
  s.directions = sphere.directions;
  for (const auto& t : sphere.triangles) s.cells.push_back({t, {}});
  Random random(3);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 view = glm::normalize(glm::vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)));
    const CellLocation at = locate_view(s, view);
    ASSERT_GE(at.cell, 0);
    EXPECT_TRUE(at.inside);  // the sphere is covered
    // The weights rebuild the view's direction through the triangle's plane.
    glm::vec3 rebuilt(0.0f);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(at.weights[size_t(k)], 0.0f);
      rebuilt += at.weights[size_t(k)] * s.directions[s.cells[size_t(at.cell)].samples[size_t(k)]];
    }
    EXPECT_GT(glm::dot(glm::normalize(rebuilt), view), 0.99999f);
  }
}

TEST(TweenDataTest, TheWarpMeshCoversTheImageWithoutFolds) {
  Random random(5);
  TweenCell cell;
  cell.samples = {0, 1};
  for (int i = 0; i < 65; ++i) {
    const glm::vec2 p(random.uniform(1.0f, 199.0f), random.uniform(1.0f, 99.0f));
    cell.points.push_back({p, p, p});
  }
  cell.points.push_back(cell.points.front());  // a duplicate is left out, not folded
  const WarpMesh mesh = build_warp_mesh(cell, 200, 100);
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const glm::vec2 a = mesh.points[t[0]][1], b = mesh.points[t[1]][1], c = mesh.points[t[2]][1];
    area += std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) / 2.0;
  }
  EXPECT_NEAR(area, 200.0 * 100.0, 1e-2);
}

// One cell alone, as a tween-data message carries it.
TEST(TweenDataTest, ACellAloneRoundTripsAndIsCheckedAgainstItsProduct) {
  const TweenData d = turntable_like(24, 65, 20.0f, 11);
  const TweenData q = quantised(d);
  for (size_t i = 3; i < d.cells.size(); i += 5) {
    const std::vector<uint8_t> bytes = encode_tween_cell(d.cells[i], d.width, d.height, d.sample_count());
    EXPECT_LE(bytes.size(), 520u);
    EXPECT_EQ(decode_tween_cell(bytes, d.width, d.height, d.sample_count()), q.cells[i]);
    // Against a product it does not belong to: a sample index past its samples, points
    // outside its smaller images.
    EXPECT_NE(test::error_of([&] { decode_tween_cell(bytes, d.width, d.height, 2); }).find("out of range"), std::string::npos);
    EXPECT_NE(test::error_of([&] { decode_tween_cell(bytes, 64, 64, d.sample_count()); }).find("outside the image"), std::string::npos);
    for (size_t cut = 0; cut < bytes.size(); ++cut)
      EXPECT_THROW(decode_tween_cell(std::span(bytes.data(), cut), d.width, d.height, d.sample_count()), Error) << cut;
    std::vector<uint8_t> longer = bytes;
    longer.push_back(0);
    EXPECT_THROW(decode_tween_cell(longer, d.width, d.height, d.sample_count()), Error);
  }
  EXPECT_THROW(decode_tween_cell(std::vector<uint8_t>(kMaxTweenCellBytes + 1, 0), 256, 256, 24), Error);
}

TEST(PointSpreadTest, OutlineFirstThenFarthestPointsAndNoneOnTopOfAnother) {
  // A square's corners and a side's midpoint on the outline; its middle, and a point 0.3 px from a
  // corner, inside.
  const std::vector<glm::vec2> layout = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {5, 0}, {5, 5}, {0.3f, 0}};
  const std::vector<bool> outline = {true, true, true, true, true, false, false};
  // The first is the one farthest from the centroid, the next the outline point farthest from it.
  const std::vector<size_t> two = spread_points(layout, outline, 2, 2);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0], 2u);
  EXPECT_EQ(two[1], 0u);
  // The five outline points first, then the middle; the point 0.3 px from a chosen corner never.
  const std::vector<size_t> all = spread_points(layout, outline, 5, 10);
  ASSERT_EQ(all.size(), 6u);
  for (size_t k = 0; k < 5; ++k) EXPECT_TRUE(outline[all[k]]) << k;
  EXPECT_EQ(all[5], 5u);
  EXPECT_TRUE(spread_points({}, {}, 3, 5).empty());
}
