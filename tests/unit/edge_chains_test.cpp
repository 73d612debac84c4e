// Chaining outline edges and simplifying chains on screen.
#include <algorithm>
#include <random>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "common/edge_chains.hpp"

using namespace inkwire;

TEST(EdgeChainsTest, JoinsPathsAndLoopsAndStopsAtBranches) {
  // A path 0-1-2-3, a triangle loop 4-5-6, and a T: 7-8, 8-9, 8-10 (branch at 8).
  const std::vector<ChainEdge> edges = {{1, 2, 0}, {0, 1, 0}, {2, 3, 0}, {4, 5, 0}, {5, 6, 0},
                                        {6, 4, 0}, {7, 8, 0}, {8, 9, 0}, {8, 10, 0}};
  ChainBuilder builder;
  const auto chains = builder.build(edges, 11);
  size_t edges_covered = 0;
  bool path = false, loop = false;
  for (const Chain& c : chains) {
    edges_covered += c.vertices.size() - 1;
    if (c.vertices.size() == 4 && ((c.vertices.front() == 0 && c.vertices.back() == 3) ||
                                   (c.vertices.front() == 3 && c.vertices.back() == 0)))
      path = true;
    if (c.vertices.size() == 4 && c.vertices.front() == c.vertices.back()) loop = true;
  }
  EXPECT_EQ(edges_covered, edges.size()) << "every edge in exactly one chain";
  for (const Chain& c : chains) {
    ASSERT_EQ(c.edges.size() + 1, c.vertices.size());
    for (size_t i = 0; i < c.edges.size(); ++i) {
      const ChainEdge& e = edges[c.edges[i]];
      EXPECT_TRUE((e.v0 == c.vertices[i] && e.v1 == c.vertices[i + 1]) || (e.v1 == c.vertices[i] && e.v0 == c.vertices[i + 1]));
    }
  }
  EXPECT_TRUE(path) << "the path is one chain from end to end";
  EXPECT_TRUE(loop) << "the triangle closes on itself";
  EXPECT_EQ(chains.size(), 2u + 3u) << "the T splits into three chains at its branch";
}

TEST(EdgeChainsTest, GroupsDoNotJoin) {
  const std::vector<ChainEdge> edges = {{0, 1, 0}, {1, 2, 1}};
  ChainBuilder builder;
  EXPECT_EQ(builder.build(edges, 3).size(), 2u);
}

TEST(EdgeChainsTest, SimplifyKeepsShapeWithinTolerance) {
  // A zig-zag of +-0.3 px along a line, with one real corner at x = 50.
  std::vector<glm::vec2> screen;
  std::vector<uint32_t> chain;
  for (int i = 0; i <= 100; ++i) {
    const float x = float(i);
    const float y = (i % 2 ? 0.3f : -0.3f) + (i > 50 ? (x - 50.0f) : 0.0f);
    screen.push_back({x, y});
    chain.push_back(uint32_t(i));
  }
  std::vector<uint32_t> out;
  simplify_chain(chain, screen, 0.75f, out);
  EXPECT_LE(out.size(), 5u) << "the zig-zag goes";
  EXPECT_EQ(out.front(), 0u);
  EXPECT_EQ(out.back(), 100u);  // positions in the chain, here equal to vertex ids
  // Every original point stays within the tolerance of the simplified polyline.
  for (size_t i = 0; i < chain.size(); ++i) {
    float best = 1e9f;
    for (size_t j = 0; j + 1 < out.size(); ++j) {
      const glm::vec2 a = screen[out[j]], b = screen[out[j + 1]], p = screen[i];
      const float t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
      best = std::min(best, glm::length(p - (a + t * (b - a))));
    }
    EXPECT_LE(best, 0.75f + 1e-4f) << "point " << i;
  }
}

TEST(EdgeChainsTest, RandomEdgeSoupIsCoveredExactlyOnce) {
  std::mt19937 rng(5);  // replayable
  std::uniform_int_distribution<uint32_t> vertex(0, 40);
  std::vector<ChainEdge> edges;
  for (int i = 0; i < 200; ++i) {
    const uint32_t a = vertex(rng), b = vertex(rng);
    if (a != b) edges.push_back({a, b, uint32_t(i % 2)});
  }
  ChainBuilder builder;
  size_t covered = 0;
  for (const Chain& c : builder.build(edges, 41)) covered += c.vertices.size() - 1;
  EXPECT_EQ(covered, edges.size());
}

TEST(EdgeChainsTest, WithPositionsChainsRunStraightThroughBranches) {
  // A cross: 0-1-2 along x and 3-1-4 along y meet at vertex 1. Without positions the branch
  // cuts them into four pieces; with positions each line is one chain.
  const std::vector<glm::vec3> positions = {{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}};
  const std::vector<ChainEdge> edges = {{0, 1, 0}, {1, 2, 0}, {3, 1, 0}, {1, 4, 0}};
  ChainBuilder builder;
  EXPECT_EQ(builder.build(edges, 5).size(), 4u);
  const auto chains = builder.build(edges, 5, &positions);
  ASSERT_EQ(chains.size(), 2u);
  for (const Chain& c : chains) {
    ASSERT_EQ(c.vertices.size(), 3u);
    EXPECT_EQ(c.vertices[1], 1u);
    const glm::vec3 a = positions[c.vertices[0]], b = positions[c.vertices[2]];
    EXPECT_NEAR(glm::length(b - a), 2.0f, 1e-6f) << "each chain is a straight line through the crossing";
  }
}
