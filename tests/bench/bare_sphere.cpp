#include "bare_sphere.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/error.hpp"

namespace inkwire::bench {

using namespace gl;

namespace {

constexpr int kRings = 54;  // 54 x 54 quads: 5 832 triangles, about the cow's 5 804

std::string read_shader(const std::string& name) {
  const std::filesystem::path path = std::filesystem::path(INKWIRE_SOURCE_DIR) / "tests/bench/shaders" / name;
  std::ifstream in(path);
  if (!in) throw Error("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

BareSphere::BareSphere()
    : vertex_source_(read_shader("bare_sphere.vert")),
      fragment_source_(read_shader("bare_sphere.frag")),
      program_(Program::from_sources({{"bare_sphere.vert", vertex_source_}, {"bare_sphere.frag", fragment_source_}})),
      vertex_array_(VertexArray::create()) {
  for (int i = 0; i <= kRings; ++i)
    for (int j = 0; j <= kRings; ++j) {
      const double polar = std::numbers::pi * i / kRings, around = 2 * std::numbers::pi * j / kRings;
      positions_.insert(positions_.end(), {float(0.7 * std::sin(polar) * std::cos(around)), float(0.7 * std::cos(polar)),
                                           float(0.7 * std::sin(polar) * std::sin(around))});
    }
  for (int i = 0; i < kRings; ++i)
    for (int j = 0; j < kRings; ++j) {
      const auto a = uint16_t(i * (kRings + 1) + j), b = uint16_t(a + kRings + 1);
      indices_.insert(indices_.end(), {a, b, uint16_t(a + 1), b, uint16_t(b + 1), uint16_t(a + 1)});
    }
  vertices_ = Buffer::create(positions_);
  index_buffer_ = Buffer::create_indices(indices_.size() * sizeof(uint16_t), indices_.data());
  vertex_array_.attribute(0, vertices_, 3, 3 * sizeof(float), 0);
  vertex_array_.bind();
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_.id());
  glBindVertexArray(0);
}

void BareSphere::draw(const FrameState& frame) {
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  program_.use();
  const float angle = bare_sphere_angle(frame.frame);
  program_.set("turn", glm::vec2(std::cos(angle), std::sin(angle)));
  vertex_array_.bind();
  glDrawElements(GL_TRIANGLES, GLsizei(indices_.size()), GL_UNSIGNED_SHORT, nullptr);
  glBindVertexArray(0);
}

std::string BareSphere::page_json() const {
  return nlohmann::json{{"positions", positions_}, {"indices", indices_}, {"vertex", vertex_source_}, {"fragment", fragment_source_}}.dump();
}

}  // namespace inkwire::bench
