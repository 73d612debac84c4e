#include "bare_frame.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "common/error.hpp"

namespace inkwire::bench {

using namespace gl;

namespace {

constexpr int kRings = 54;  // 54 x 54 quads: 5 832 triangles, about the cow's 5 804

std::string read_shader(BareFrame::Kind kind, const std::string& stage) {
  const std::filesystem::path path =
      std::filesystem::path(INKWIRE_SOURCE_DIR) / "tests/bench/shaders" / ((kind == BareFrame::Kind::Mesh ? "bare_mesh" : "bare_quads") + stage);
  std::ifstream in(path);
  if (!in) throw Error("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

BareFrame::BareFrame(Kind kind)
    : kind_(kind),
      vertex_source_(read_shader(kind, ".vert")),
      fragment_source_(read_shader(kind, ".frag")),
      program_(Program::from_sources({{"bare.vert", vertex_source_}, {"bare.frag", fragment_source_}})),
      vertex_array_(VertexArray::create()) {
  if (kind_ == Kind::Mesh) {
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
  } else {
    // Scattered over a 300-pixel square in the middle of the 620x500 frame, as brushes over an
    // object: about 16 layers deep.
    uint32_t state = 1;
    const auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) / float(1u << 24); };
    for (int i = 0; i < kBareQuads; ++i) positions_.insert(positions_.end(), {160.0f + 300.0f * next(), 100.0f + 300.0f * next()});
  }
  vertices_ = Buffer::create(positions_);
  if (kind_ == Kind::Mesh) {
    vertex_array_.attribute(0, vertices_, 3, 3 * sizeof(float), 0);
    index_buffer_ = Buffer::create_indices(indices_.size() * sizeof(uint16_t), indices_.data());
    vertex_array_.bind();
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_.id());
  } else {
    vertex_array_.attribute(0, vertices_, 2, 2 * sizeof(float), 0);
    glVertexAttribDivisor(0, 1);
  }
  glBindVertexArray(0);
}

void BareFrame::draw(const FrameState& frame) {
  program_.use();
  vertex_array_.bind();
  if (kind_ == Kind::Mesh) {
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    const float angle = bare_frame_angle(frame.frame);
    program_.set("turn", glm::vec2(std::cos(angle), std::sin(angle)));
    glDrawElements(GL_TRIANGLES, GLsizei(indices_.size()), GL_UNSIGNED_SHORT, nullptr);
  } else {
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    program_.set("viewport", glm::vec2(frame.viewport));
    program_.set("shift", glm::vec2(bare_frame_shift(frame.frame)));
    program_.set("half_size", kBareQuadHalfSize);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, kBareQuads);
    glDisable(GL_BLEND);
  }
  glBindVertexArray(0);
}

nlohmann::json BareFrame::page_json() const {
  nlohmann::json j = {{"name", name()}, {"vertex", vertex_source_}, {"fragment", fragment_source_}};
  if (kind_ == Kind::Mesh) j["positions"] = positions_, j["indices"] = indices_;
  else j["centres"] = positions_, j["half_size"] = kBareQuadHalfSize;
  return j;
}

}  // namespace inkwire::bench
