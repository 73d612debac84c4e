// Sketch logic without GL: importance (S1), perturbation (S2), fading (S6), hidden valleys.
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "client/render/sketch/importance.hpp"
#include "client/render/sketch/perturb.hpp"
#include "client/render/sketch/segment_sketcher.hpp"
#include "client/render/sketch/sketch_edges.hpp"
#include "common/error.hpp"
#include "common/mesh_import.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::test;

TEST(SketchTest, ImportanceDropsOnlyEdgesThatAreBothShortAndFlat) {
  const ImportanceOptions o{.min_length = 1.0f, .max_angle = 0.5f};
  struct Case {
    float length, dihedral;
    bool kept;
  };
  for (const Case& c : {Case{0.5f, 0.1f, false},   // short and flat: dropped
                        Case{0.5f, 0.9f, true},    // short crease: kept
                        Case{2.0f, 0.1f, true},    // long flat edge: kept
                        Case{2.0f, 0.9f, true},    // long crease: kept
                        Case{1.0f, 0.1f, true},    // exactly the minimum length is not short
                        Case{0.5f, 0.5f, true}}) { // exactly the angle is not flat
    Edge e{};
    e.length = c.length;
    e.dihedral = c.dihedral;
    EXPECT_EQ(statically_important(e, o), c.kept) << "length " << c.length << ", angle " << c.dihedral;
  }
}

TEST(SketchTest, ImportanceCountsOnARealMeshAndFlaggedEdgesStay) {
  const auto file = cgal_mesh("cow.off");
  INKWIRE_REQUIRE_FILE(file);
  const Mesh cow = load_mesh(file);
  const Topology topo = build_topology(cow);
  const float diag = topo.bounds.diagonal();
  const auto length_only = important_edges(topo, {.min_length = 0.02f * diag, .max_angle = 10.0f});
  const auto angle_only = important_edges(topo, {.min_length = 10.0f * diag, .max_angle = 0.3f});
  const auto both = important_edges(topo, {.min_length = 0.02f * diag, .max_angle = 0.3f});
  EXPECT_LT(both.size(), topo.edges.size());
  EXPECT_GE(both.size(), std::max(length_only.size(), angle_only.size())) << "dropped only when both tests drop";
  std::printf("cow: %zu edges; kept by MinLength alone %zu, by MaxAngle alone %zu, by the S1 rule %zu\n", topo.edges.size(),
              length_only.size(), angle_only.size(), both.size());
  // A flagged edge that the rule drops comes back.
  const auto dropped_everything = important_edges(topo, {.min_length = 10.0f * diag, .max_angle = 4.0f});
  EXPECT_TRUE(dropped_everything.empty());
  const Edge& e = topo.edges[17];
  const auto flagged = load_flagged_edges(write_temp("flags.txt", "# keep this one\n" + std::to_string(e.v1) + " " + std::to_string(e.v0) + "\n"),
                                          topo, cow.positions.size());
  EXPECT_EQ(important_edges(topo, {.min_length = 10.0f * diag, .max_angle = 4.0f}, flagged), std::vector<uint32_t>{17});
  EXPECT_THROW(load_flagged_edges(write_temp("bad1.txt", "1\n"), topo, cow.positions.size()), Error);
  EXPECT_THROW(load_flagged_edges(write_temp("bad2.txt", "1 99999999\n"), topo, cow.positions.size()), Error);
  EXPECT_THROW(load_flagged_edges(write_temp("bad3.txt", "0 1 2\n"), topo, cow.positions.size()), Error);
}

TEST(SketchTest, RecursiveSubdivisionStaysShortAndClose) {
  std::mt19937 rng(3);  // replayable
  std::uniform_real_distribution<float> coord(-5.0f, 5.0f);
  const PerturbOptions o{.max_segment = 0.3f, .amplitude_ratio = 0.05f, .amplitude_clamp = 0.1f};
  for (int trial = 0; trial < 200; ++trial) {
    const glm::vec3 a(coord(rng), coord(rng), coord(rng)), b(coord(rng), coord(rng), coord(rng));
    const glm::vec3 side = glm::normalize(glm::cross(b - a, glm::vec3(0.3f, 0.8f, 0.5f)));
    StrokeRandom random(stroke_seed(uint64_t(trial), 1));
    std::vector<glm::vec3> line;
    perturb_edge(a, b, side, o, random, line);
    ASSERT_GE(line.size(), 2u);
    const float amplitude = perturb_amplitude(glm::length(b - a), o);
    EXPECT_LE(amplitude, o.amplitude_clamp);
    for (size_t i = 0; i + 1 < line.size(); ++i)
      EXPECT_LE(glm::length(line[i + 1] - line[i]), o.max_segment + 1e-5f) << "segment " << i << " too long";
    for (const glm::vec3& p : line) {
      const float t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
      EXPECT_LE(glm::length(p - (a + t * (b - a))), amplitude + 1e-5f) << "point strays beyond the clamped amplitude";
    }
  }
}

TEST(SketchTest, SameSeedSameStroke) {
  const PerturbOptions o{};
  std::vector<glm::vec3> first, second, other;
  StrokeRandom r1(stroke_seed(5, 2)), r2(stroke_seed(5, 2)), r3(stroke_seed(5, 3));
  perturb_edge({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, o, r1, first);
  perturb_edge({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, o, r2, second);
  perturb_edge({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, o, r3, other);
  EXPECT_EQ(first, second);
  EXPECT_NE(first, other);
}

TEST(SketchTest, FadingStopsEdgesPoppingAsTheObjectTurns) {
  // Turn the cow in 0.5-degree steps and follow every edge's opacity: with fading on, none
  // jumps from 0 to 1 in one step; with fading off (a step function) some do.
  const auto file = cgal_mesh("cow.off");
  INKWIRE_REQUIRE_FILE(file);
  const Mesh cow = load_mesh(file);
  const Topology topo = build_topology(cow);
  std::vector<uint32_t> all(topo.edges.size());
  for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  auto opacities = [&](float degrees, bool fading) {
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 1, 0));
    const glm::vec3 eye = glm::vec3(glm::inverse(turn) * glm::vec4(topo.bounds.centre() + glm::vec3(0, 0.3f, 2.0f) * topo.bounds.diagonal(), 1.0f));
    std::vector<DrawnEdge> drawn;
    choose_sketch_edges(cow, topo, all, eye, 10.0f /* no creases */, {.enabled = fading, .range_degrees = 5.0f}, drawn);
    std::vector<float> opacity(topo.edges.size(), 0.0f);
    for (const DrawnEdge& d : drawn) opacity[d.edge] = d.opacity;
    return opacity;
  };
  for (bool fading : {true, false}) {
    size_t pops = 0;
    std::vector<float> before = opacities(0.0f, fading);
    for (float deg = 0.5f; deg <= 90.0f; deg += 0.5f) {
      const std::vector<float> after = opacities(deg, fading);
      for (size_t i = 0; i < after.size(); ++i) pops += before[i] == 0.0f && after[i] == 1.0f;
      before = after;
    }
    if (fading) EXPECT_EQ(pops, 0u) << "edges popped in with fading on";
    else EXPECT_GT(pops, 0u) << "without fading edges should pop (or the test proves nothing)";
  }
}

TEST(SketchTest, WholeStrokesWobbleWithinTheirAmplitude) {
  // A quarter circle of 40 short edges: perturbed as one stroke it wobbles by an amount set by
  // its whole length, and never strays further than that from the curve.
  std::vector<glm::vec3> points, sides;
  for (int i = 0; i <= 40; ++i) {
    const float a = 1.5707963f * float(i) / 40.0f;
    points.push_back({std::cos(a), std::sin(a), 0.0f});
    sides.push_back({std::cos(a), std::sin(a), 0.0f});  // outward, across the curve
  }
  const PerturbOptions o{.max_segment = 0.02f, .amplitude_ratio = 0.05f, .amplitude_clamp = 1.0f};
  const float amplitude = perturb_amplitude(1.5707963f, o);
  float largest = 0.0f;
  for (uint64_t seed = 0; seed < 50; ++seed) {
    StrokeRandom random(stroke_seed(seed, 9));
    std::vector<glm::vec3> out;
    perturb_stroke(points, sides, o, random, out);
    for (size_t i = 0; i + 1 < out.size(); ++i) ASSERT_LE(glm::length(out[i + 1] - out[i]), o.max_segment + 1e-5f);
    for (const glm::vec3& p : out) {
      const float off = std::abs(glm::length(glm::vec2(p)) - 1.0f);  // distance from the arc
      EXPECT_LE(off, amplitude + 1e-4f);
      largest = std::max(largest, off);
    }
  }
  EXPECT_GT(largest, 0.25f * amplitude) << "a whole stroke should visibly wobble, not just each tiny edge";
}

TEST(SketchTest, UnitLinesWobbleAlikePerUnitLengthInEveryBin) {
  // S4: lines made once at load time, in length bins. Mapped onto an edge of its bin's typical
  // length, each line's sideways wobble (y times the length) stays within the absolute
  // amplitude a stroke of that length gets, so short and long edges look alike.
  const float diagonal = 10.0f;
  const PerturbOptions o{.max_segment = 0.2f, .amplitude_ratio = 0.05f, .amplitude_clamp = 0.06f};
  const UnitLines lines = make_unit_lines(diagonal, o, 8);
  ASSERT_EQ(lines.bin_upper.size(), lines.points.size());
  const float typical[] = {0.003f, 0.009f, 0.025f, 0.065f, 0.15f};
  for (size_t b = 0; b < lines.points.size(); ++b) {
    SCOPED_TRACE(b);
    const float length = typical[b] * diagonal;
    EXPECT_EQ(lines.bin_of(length), int(b));
    const float amplitude = perturb_amplitude(length, o);
    for (int l = 0; l < lines.lines; ++l) {
      const glm::vec2* p = &lines.data[size_t(lines.first[b] + l * lines.points[b])];
      EXPECT_NEAR(p[0].x, 0.0f, 0.3f);
      EXPECT_NEAR(p[lines.points[b] - 1].x, 1.0f, 0.3f);
      for (int i = 0; i < lines.points[b]; ++i) EXPECT_LE(std::abs(p[i].y) * length, amplitude + 1e-5f);
    }
  }
}

TEST(SketchTest, ClosedOrientedSurfaceNeedsEveryEdgePairedFrontToBack) {
  Mesh tetrahedron;
  tetrahedron.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};  // counter-clockwise from outside
  EXPECT_TRUE(is_closed_oriented_surface(tetrahedron));
  Mesh open = tetrahedron;
  open.triangles.pop_back();
  EXPECT_FALSE(is_closed_oriented_surface(open)) << "a hole";
  Mesh flipped = tetrahedron;
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  EXPECT_FALSE(is_closed_oriented_surface(flipped)) << "one face turned inside out";
}

namespace {

// Whether the segment from `from` to `to` passes through a triangle of `mesh` (other than the
// faces in `skip`) before reaching `to` (Moller-Trumbore).
bool blocked(const Mesh& mesh, const glm::vec3& from, const glm::vec3& to, uint32_t skip0, uint32_t skip1) {
  const glm::vec3 d = to - from;
  for (uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    if (f == skip0 || f == skip1) continue;
    const glm::vec3 a = mesh.positions[mesh.triangles[f][0]], b = mesh.positions[mesh.triangles[f][1]],
                    c = mesh.positions[mesh.triangles[f][2]];
    const glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) continue;
    const glm::vec3 s = from - a;
    const float u = glm::dot(s, p) / det;
    if (u < 0.0f || u > 1.0f) continue;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(d, q) / det;
    if (v < 0.0f || u + v > 1.0f) continue;
    const float t = glm::dot(e2, q) / det;
    if (t > 0.0f && t < 1.0f - 1e-5f) return true;
  }
  return false;
}

}  // namespace

TEST(SketchTest, ValleySilhouettesOfAClosedMeshAreHiddenAndLeftOut) {
  // Cast a ray from the eye to the middle of every silhouette edge of a closed mesh: each one
  // on a valley meets the surface first; many on ridges do not (so the ray cast can tell).
  const auto file = cgal_mesh("cow.off");
  INKWIRE_REQUIRE_FILE(file);
  const Mesh cow = load_mesh(file);
  const Topology topo = build_topology(cow);
  ASSERT_TRUE(is_closed_oriented_surface(cow));
  const std::vector<uint8_t> valleys = valley_edges_of_closed_mesh(cow, topo);
  ASSERT_EQ(valleys.size(), topo.edges.size());
  std::vector<uint32_t> all(topo.edges.size());
  for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  size_t valley_silhouettes = 0, valleys_seen = 0, ridge_silhouettes = 0, ridges_seen = 0;
  for (float degrees : {0.0f, 60.0f, 135.0f, 200.0f, 290.0f}) {
    const glm::vec3 eye = topo.bounds.centre() +
                          topo.bounds.diagonal() * glm::vec3(std::sin(glm::radians(degrees)), 0.35f, std::cos(glm::radians(degrees)));
    for (uint32_t i = 0; i < topo.edges.size(); ++i) {
      const Edge& e = topo.edges[i];
      const glm::vec3 mid = 0.5f * (cow.positions[e.v0] + cow.positions[e.v1]);
      if (glm::dot(topo.face_normals[e.f0], eye - mid) * glm::dot(topo.face_normals[e.f1], eye - mid) >= 0.0f) continue;
      const bool seen = !blocked(cow, eye, mid, e.f0, e.f1);
      if (valleys[i]) ++valley_silhouettes, valleys_seen += seen;
      else ++ridge_silhouettes, ridges_seen += seen;
    }
    std::vector<DrawnEdge> with, without;
    choose_sketch_edges(cow, topo, all, eye, 10.0f /* no creases */, {}, with, valleys);
    choose_sketch_edges(cow, topo, all, eye, 10.0f, {}, without);
    for (const DrawnEdge& d : with) EXPECT_FALSE(valleys[d.edge]) << "a valley silhouette was drawn";
    EXPECT_LT(with.size(), without.size());
  }
  EXPECT_GT(valley_silhouettes, 100u);
  EXPECT_EQ(valleys_seen, 0u) << "of " << valley_silhouettes << " valley silhouettes";
  EXPECT_GT(ridges_seen, ridge_silhouettes / 4) << "the ray cast finds everything hidden: it proves nothing";
}

TEST(SketchTest, ValleysStayWhenTheEyeIsInsideTheBounds) {
  // Inside the object the argument fails (the eye may be inside the solid): every silhouette
  // is drawn; outside, the valley ones are left out.
  const auto file = cgal_mesh("cow.off");
  INKWIRE_REQUIRE_FILE(file);
  const SceneObject cow = make_scene_object(load_mesh(file));
  SketchEdgeSource source;
  source.configure(StyleParams(SketchEdgeSource::params(false)));
  source.prepare(cow);
  const Bounds& b = cow.topology.bounds;
  // The source's candidates under its default thresholds, for the same choice with no valleys.
  std::vector<uint32_t> candidates;
  for (uint32_t i = 0; i < cow.topology.edges.size(); ++i)
    if (statically_important(cow.topology.edges[i], {0.01f * b.diagonal(), glm::radians(12.0f)})) candidates.push_back(i);
  for (const glm::vec3& eye : {b.centre(), b.centre() + glm::vec3(0.0f, 0.2f, 1.5f) * b.diagonal()}) {
    const size_t drawn = source.choose(eye).size();
    std::vector<DrawnEdge> every;
    choose_sketch_edges(cow.mesh, cow.topology, candidates, eye, glm::radians(50.0f), {}, every);
    if (eye == b.centre()) EXPECT_EQ(drawn, every.size()) << "eye inside the bounds";
    else EXPECT_LT(drawn, every.size()) << "eye outside the bounds";
  }
}
