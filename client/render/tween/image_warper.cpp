#include "client/render/tween/image_warper.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "common/error.hpp"

namespace inkwire {

using namespace gl;
namespace {

constexpr float kFirstLayerDepth = 0.5f;
constexpr float kLayerStep = 0.05f;  // 3 passes fit easily between the cleared depth (1) and 0

}  // namespace

gl::Texture make_sample_texture(const Image& image) {
  Image premultiplied = image;
  for (size_t i = 0; i < premultiplied.pixels.size(); i += 4) {
    const unsigned a = premultiplied.pixels[i + 3];
    for (int c = 0; c < 3; ++c) premultiplied.pixels[i + c] = uint8_t((premultiplied.pixels[i + c] * a + 127) / 255);
  }
  return gl::Texture::from_image(premultiplied, {.repeat = false, .mipmaps = false, .linear = true});
}

gl::Texture make_matte_texture(const Image& image, double scale) {
  return gl::Texture::from_image(matte_sample(image, scale), {.repeat = false, .mipmaps = false, .linear = true});
}

ImageWarper::ImageWarper(int width, int height)
    : width_(width),
      height_(height),
      warp_(gl::Program::from_files({"tween/warp.vert", "tween/warp.frag"})),
      composite_(gl::Program::from_files({"tween/composite.vert", "tween/composite.frag"})),
      target_(gl::Texture::from_image(Image(width, height), {.repeat = false, .mipmaps = false, .linear = true})),
      depth_(gl::Renderbuffer::create(GL_DEPTH_COMPONENT24, width, height, 0)),
      fbo_(gl::Framebuffer::create()),
      empty_vao_(gl::VertexArray::create()) {
  const FramebufferBinding restore;
  fbo_.bind();
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target_.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  fbo_.check_complete("ImageWarper target");
}

const gl::Program& ImageWarper::blend_program(size_t sources) const {
  std::optional<gl::Program>& program = (matte_ ? blend_matte_ : blend_)[sources - 1];
  if (!program) {
    std::vector<std::string> defines = {"SAMPLES " + std::to_string(sources)};
    if (matte_) defines.insert(defines.end(), {"MATTE", "MATTE_RANGE " + std::to_string(kMatteRange), "BLEED " + std::to_string(kBleedPixels)});
    program = gl::Program::from_files({"tween/blend.vert", "tween/blend.frag"}, defines);
  }
  return *program;
}

namespace {

std::vector<float> vertex_data(const WarpMesh& mesh) {
  std::vector<float> vertices;
  vertices.reserve(mesh.points.size() * 6);
  for (const ControlPoint& p : mesh.points)
    for (const glm::vec2& v : p) vertices.insert(vertices.end(), {v.x, v.y});
  return vertices;
}

}  // namespace

int ImageWarper::add_mesh(const WarpMesh& mesh) {
  const std::vector<float> vertices = vertex_data(mesh);
  std::vector<uint32_t> indices;
  for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
  Mesh m{gl::Buffer::create(vertices), gl::Buffer::create_indices(indices), mesh.points.size(), gl::VertexArray::create(), GLsizei(indices.size())};
  for (GLuint k = 0; k < 3; ++k) m.vao.attribute(k, m.vertices, 2, 6 * sizeof(float), k * 2 * sizeof(float));
  m.vao.bind();
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.indices.id());  // recorded in the bound vertex array
  glBindVertexArray(0);
  meshes_.push_back(std::move(m));
  return int(meshes_.size()) - 1;
}

void ImageWarper::update_mesh(int mesh, const WarpMesh& moved) {
  Mesh& m = meshes_.at(size_t(mesh));
  if (moved.points.size() != m.points) throw Error("ImageWarper::update_mesh(): the point count changed");
  const std::vector<float> vertices = vertex_data(moved);
  m.vertices.upload(vertices.size() * sizeof(float), vertices.data(), GL_DYNAMIC_DRAW);
}

void ImageWarper::update_triangles(int mesh, std::span<const std::array<uint32_t, 3>> triangles) {
  Mesh& m = meshes_.at(size_t(mesh));
  if (GLsizei(triangles.size() * 3) != m.index_count) throw Error("ImageWarper::update_triangles(): the triangle count changed");
  m.indices.upload(triangles.size_bytes(), triangles.data(), GL_DYNAMIC_DRAW);
}

void ImageWarper::blend(int mesh, const glm::vec3& position_weights, std::span<const WarpSource> sources,
                        const glm::vec4& to_clip) const {
  if (sources.empty() || sources.size() > 3) throw Error("ImageWarper: a view is made of 1 to 3 samples");
  const Mesh& m = meshes_.at(size_t(mesh));
  const gl::Program& program = blend_program(sources.size());
  program.use();
  glm::ivec3 source(0);
  glm::vec3 weights(0.0f);
  for (size_t k = 0; k < sources.size(); ++k) {
    const WarpSource& s = sources[k];
    source[int(k)] = std::clamp(s.position, 0, 2);
    weights[int(k)] = s.weight;
    static constexpr const char* kSampler[] = {"samples[0]", "samples[1]", "samples[2]"};
    static constexpr const char* kSize[] = {"sample_size[0]", "sample_size[1]", "sample_size[2]"};
    program.set(kSampler[k], int(k));
    program.set(kSize[k], glm::vec2(s.image->width(), s.image->height()) / s.scale);
    s.image->bind(GLuint(k));
  }
  program.set("position_weights", position_weights);
  program.set("source", source);
  program.set("weights", weights);
  program.set("to_clip", to_clip);
  program.set("depth", kFirstLayerDepth);
  glDisable(GL_CULL_FACE);  // folded triangles face away and still carry colour
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over"
  m.vao.bind();
  glDrawElements(GL_TRIANGLES, m.index_count, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ZERO);
}

void ImageWarper::render(int mesh, const glm::vec3& position_weights, std::span<const WarpSource> sources) {
  const FramebufferBinding restore;
  fbo_.bind();
  glViewport(0, 0, width_, height_);
  glDisable(GL_SCISSOR_TEST);
  glDepthMask(GL_TRUE);
  glClearColor(0, 0, 0, 0);
  glClearDepthf(1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // Pixels (y down) to clip space, the image's top row at the top.
  blend(mesh, position_weights, sources, {2.0f / float(width_), -2.0f / float(height_), -1.0f, 1.0f});
}

void ImageWarper::draw_over(int mesh, const glm::vec3& position_weights, std::span<const WarpSource> sources,
                            const glm::vec4& rect) const {
  glm::ivec4 bound;
  glGetIntegerv(GL_VIEWPORT, &bound.x);
  const glm::vec4 viewport(bound);
  // Image pixel (y down) -> window pixel in rect (y up, the image's top row at the rect's top)
  // -> clip space of the bound viewport.
  const glm::vec4 to_clip(2.0f * rect.z / (float(width_) * viewport.z), -2.0f * rect.w / (float(height_) * viewport.w),
                          2.0f * (rect.x - viewport.x) / viewport.z - 1.0f, 2.0f * (rect.y + rect.w - viewport.y) / viewport.w - 1.0f);
  blend(mesh, position_weights, sources, to_clip);
}

void ImageWarper::begin(OverlapMode overlap) {
  caller_ = std::make_unique<FramebufferBinding>();
  overlap_ = overlap;
  passes_ = 0;
  fbo_.bind();
  glViewport(0, 0, width_, height_);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);  // folded triangles face away and still carry colour
  glDepthMask(GL_TRUE);
  glClearColor(0, 0, 0, 0);
  glClearDepthf(1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  warp_.use();
  warp_.set("image_size", glm::vec2(width_, height_));
  warp_.set("sample_image", 0);
}

void ImageWarper::pass(int mesh, const gl::Texture& sample, const glm::vec3& position_weights, int source, float weight, float scale) {
  if (!caller_) throw Error("ImageWarper::pass(): called outside begin()/end()");
  const Mesh& m = meshes_.at(size_t(mesh));
  float depth = 0.0f;
  if (overlap_ == OverlapMode::DepthClear) {
    glClear(GL_DEPTH_BUFFER_BIT);
  } else {
    depth = kFirstLayerDepth - kLayerStep * float(passes_);
  }
  warp_.set("position_weights", position_weights);
  warp_.set("source", std::clamp(source, 0, 2));
  warp_.set("weight", weight);
  warp_.set("sample_size", glm::vec2(sample.width(), sample.height()) / scale);
  warp_.set("depth", depth);
  sample.bind(0);
  m.vao.bind();
  glDrawElements(GL_TRIANGLES, m.index_count, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
  ++passes_;
}

void ImageWarper::end() {
  glDisable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ZERO);
  caller_.reset();
}

Image ImageWarper::read() const {
  const FramebufferBinding restore;
  fbo_.bind(GL_READ_FRAMEBUFFER);
  Image image(width_, height_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  flip_rows(image);
  return image;
}

void ImageWarper::composite(const glm::vec4& rect) const {
  glm::ivec4 viewport;
  glGetIntegerv(GL_VIEWPORT, &viewport.x);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  composite_.use();
  composite_.set("viewport", glm::vec4(viewport));
  composite_.set("rect", rect);
  composite_.set("view_image", 0);
  target_.bind(0);
  empty_vao_.bind();
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ZERO);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace inkwire
