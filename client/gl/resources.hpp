#pragma once
// Small RAII owners of GL objects. Each is move-only and deletes its object in the context that
// is current when it dies (all of ours live and die within one context).
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat2x2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "client/gl/gl.hpp"
#include "common/image.hpp"

namespace inkwire::gl {

// Holds a GL name and the function that deletes it.
template <void (*Delete)(GLuint)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  ~Handle() { reset(); }
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) Delete(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

void delete_buffer(GLuint id);
void delete_vertex_array(GLuint id);
void delete_texture(GLuint id);
void delete_program(GLuint id);
void delete_framebuffer(GLuint id);
void delete_renderbuffer(GLuint id);

// Vertex data goes in through the GL_COPY_WRITE_BUFFER binding point, which no vertex array
// records. WebGL2 keeps index buffers apart from all others (a buffer once bound anywhere else
// can never hold indices), so index buffers are made as such and filled through
// GL_ELEMENT_ARRAY_BUFFER with no vertex array bound: uploading never swaps the element buffer
// of whatever vertex array is bound.
class Buffer : public Handle<delete_buffer> {
 public:
  static Buffer create(size_t bytes, const void* data, GLenum usage = GL_STATIC_DRAW);
  template <typename T>
  static Buffer create(const std::vector<T>& items, GLenum usage = GL_STATIC_DRAW) {
    return create(items.size() * sizeof(T), items.data(), usage);
  }
  // A buffer of indices (GL_ELEMENT_ARRAY_BUFFER when drawing).
  static Buffer create_indices(size_t bytes, const void* data, GLenum usage = GL_STATIC_DRAW);
  static Buffer create_indices(const std::vector<uint32_t>& indices, GLenum usage = GL_STATIC_DRAW) {
    return create_indices(indices.size() * sizeof(uint32_t), indices.data(), usage);
  }
  // Replaces the contents, growing the store when needed (for per-frame streamed data).
  void upload(size_t bytes, const void* data, GLenum usage = GL_STREAM_DRAW);
  size_t capacity() const { return capacity_; }

 private:
  using Handle::Handle;
  size_t capacity_ = 0;
  GLenum target_ = GL_COPY_WRITE_BUFFER;  // where it is filled
};

class VertexArray : public Handle<delete_vertex_array> {
 public:
  static VertexArray create();
  void bind() const { glBindVertexArray(id()); }
  // Float attribute `index` read from `buffer` (bound as GL_ARRAY_BUFFER).
  void attribute(GLuint index, const Buffer& buffer, GLint components, GLsizei stride, size_t offset,
                 GLenum type = GL_FLOAT, bool normalised = false);

 private:
  using Handle::Handle;
};

struct TextureOptions {
  bool repeat = true;
  bool clamp_t = false;  // clamp across t even when repeating along s (stroke strips)
  bool mipmaps = true;
  bool linear = true;
};

class Texture : public Handle<delete_texture> {
 public:
  static Texture from_image(const Image& image, const TextureOptions& options = {});
  // Equal-sized images stacked into one texture: GL_TEXTURE_2D_ARRAY (layers picked by index,
  // e.g. stroke variants) or GL_TEXTURE_3D (filtered along the stack too, e.g. hatch tones).
  static Texture stack_from_images(const std::vector<Image>& layers, GLenum target, const TextureOptions& options = {});
  // A lookup table (shade maps, tone ramps): one row of RGBA texels as a 2D texture one texel
  // high (1D textures are desktop GL's alone; WebGL2 has none), read at v = 0.5.
  static Texture lookup_row(const std::vector<glm::u8vec4>& texels, bool linear);
  // Data a shader reads by index (texelFetch through common/data_texture.glsl): RGBA float texels
  // laid kDataTextureWidth to a row. What storage buffers do on desktop GL, which WebGL2 lacks.
  static Texture data_rows(const std::vector<glm::vec4>& texels);
  static constexpr int kDataTextureWidth = 1024;
  // A 24-bit depth and 8-bit stencil target a shader can read (texelFetch), nearest-filtered.
  static Texture depth_stencil(int width, int height);
  // Replaces a data texture's texels (per-frame data), reallocating only when it must grow.
  void update_rows(const std::vector<glm::vec4>& texels);
  // Replaces a 2D texture's texels (per-frame images: captures, video frames); reallocates
  // only when the size changes. Mipmaps, if any, are regenerated.
  void update(const Image& image);
  void bind(int unit) const;
  // From now on reads only mipmap `level` (clamped to the chain), bilinearly: the level that
  // trilinear filtering would pick, chosen once by the caller for many draws of one size,
  // without trilinear filtering's cost per pixel. Textures made without mipmaps stay at 0.
  // Binds the texture to the active unit.
  void sample_level(int level) const;
  // Filters linearly or takes the nearest texel, from now on. Binds the texture to the active
  // unit.
  void set_filter(bool linear) const;
  GLenum target() const { return target_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  using Handle::Handle;
  static Texture create_bound(GLenum target);  // new texture, bound, ready for upload
  GLenum target_ = GL_TEXTURE_2D;
  int width_ = 0, height_ = 0;
  bool mipmaps_ = false;
};

// Shader stage sources by their embedded path under client/shaders/ (e.g. "default/mesh.vert"),
// each line `#include "common/x.glsl"` replaced by that file (code several shaders share, such
// as common/wide_line.glsl). Throws inkwire::Error when no such file was embedded.
const std::string& shader_source(const std::string& path);

// What every shader is compiled after: the target's #version line (GLSL 3.30 core natively,
// GLSL ES 3.00 for WebGL2) and, for ES, default precisions. The ES one is also the header of the
// browser element's own tween shaders (client/web/render/tween/tween_view.js, pinned by
// warp-vectors.json "shader_header").
inline constexpr const char* kWebGlShaderHeader =
    "#version 300 es\n"
    "precision highp float;\nprecision highp int;\n"
    "precision highp sampler2D;\nprecision highp sampler2DArray;\nprecision highp sampler3D;\n";
const std::string& shader_header();

class Program : public Handle<delete_program> {
 public:
  // Compiles and links the stages named by embedded path; `defines` follow the
  // target's header (shader_header()) as "#define NAME VALUE" lines (variants). Throws inkwire::Error carrying the
  // driver's log prefixed by "Program::compile(): <path>:" or "Program::link():".
  static Program from_files(const std::vector<std::string>& stage_paths, const std::vector<std::string>& defines = {});
  // Same, from literal sources (first element of each pair is a name for error messages).
  static Program from_sources(const std::vector<std::pair<std::string, std::string>>& named_sources,
                              const std::vector<std::string>& defines = {});

  void use() const { glUseProgram(id()); }
  GLint location(const char* name) const;
  void set(const char* name, int v) const { glUniform1i(location(name), v); }
  void set(const char* name, float v) const { glUniform1f(location(name), v); }
  void set(const char* name, const glm::vec2& v) const { glUniform2f(location(name), v.x, v.y); }
  void set(const char* name, const glm::vec3& v) const { glUniform3f(location(name), v.x, v.y, v.z); }
  void set(const char* name, const glm::ivec3& v) const { glUniform3i(location(name), v.x, v.y, v.z); }
  void set(const char* name, const glm::vec4& v) const { glUniform4f(location(name), v.x, v.y, v.z, v.w); }
  void set(const char* name, const glm::mat2& m) const { glUniformMatrix2fv(location(name), 1, GL_FALSE, &m[0][0]); }
  void set(const char* name, const glm::mat3& m) const { glUniformMatrix3fv(location(name), 1, GL_FALSE, &m[0][0]); }
  void set(const char* name, const glm::mat4& m) const { glUniformMatrix4fv(location(name), 1, GL_FALSE, &m[0][0]); }

 private:
  using Handle::Handle;
  mutable std::map<std::string, GLint, std::less<>> locations_;
};

class Renderbuffer : public Handle<delete_renderbuffer> {
 public:
  static Renderbuffer create(GLenum format, int width, int height, int samples);

 private:
  using Handle::Handle;
};

class Framebuffer : public Handle<delete_framebuffer> {
 public:
  static Framebuffer create();
  void bind(GLenum target = GL_FRAMEBUFFER) const { glBindFramebuffer(target, id()); }
  // Throws inkwire::Error naming the incompleteness reason.
  void check_complete(const char* what) const;

 private:
  using Handle::Handle;
};

}  // namespace inkwire::gl
