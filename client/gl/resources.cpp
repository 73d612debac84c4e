#include "client/gl/resources.hpp"

#include <algorithm>
#include <sstream>

#include "common/error.hpp"

namespace inkwire {
const std::map<std::string, std::string_view>& embedded_files();  // generated from client/shaders
}

namespace inkwire::gl {

void delete_buffer(GLuint id) { glDeleteBuffers(1, &id); }
void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }
void delete_texture(GLuint id) { glDeleteTextures(1, &id); }
void delete_program(GLuint id) { glDeleteProgram(id); }
void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void delete_renderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }

Buffer Buffer::create(size_t bytes, const void* data, GLenum usage) {
  GLuint id = 0;
  glGenBuffers(1, &id);
  Buffer b(id);
  b.upload(bytes, data, usage);
  return b;
}

Buffer Buffer::create_indices(size_t bytes, const void* data, GLenum usage) {
  GLuint id = 0;
  glGenBuffers(1, &id);
  Buffer b(id);
  b.target_ = GL_ELEMENT_ARRAY_BUFFER;
  b.upload(bytes, data, usage);
  return b;
}

void Buffer::upload(size_t bytes, const void* data, GLenum usage) {
  GLint vertex_array = 0;
  if (target_ == GL_ELEMENT_ARRAY_BUFFER) {  // the element binding belongs to the bound vertex array
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array);
    glBindVertexArray(0);
  }
  glBindBuffer(target_, id());
  if (bytes > capacity_ || capacity_ == 0) {
    glBufferData(target_, GLsizeiptr(std::max<size_t>(bytes, 1)), data, usage);
    capacity_ = std::max<size_t>(bytes, 1);
  } else if (bytes > 0) {
    glBufferSubData(target_, 0, GLsizeiptr(bytes), data);
  }
  glBindBuffer(target_, 0);
  if (target_ == GL_ELEMENT_ARRAY_BUFFER) glBindVertexArray(GLuint(vertex_array));
}

VertexArray VertexArray::create() {
  GLuint id = 0;
  glGenVertexArrays(1, &id);
  return VertexArray(id);
}

void VertexArray::attribute(GLuint index, const Buffer& buffer, GLint components, GLsizei stride, size_t offset,
                            GLenum type, bool normalised) {
  bind();
  glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
  glEnableVertexAttribArray(index);
  if (type == GL_FLOAT || normalised)
    glVertexAttribPointer(index, components, type, normalised ? GL_TRUE : GL_FALSE, stride,
                          reinterpret_cast<const void*>(offset));
  else
    glVertexAttribIPointer(index, components, type, stride, reinterpret_cast<const void*>(offset));
}

Texture Texture::create_bound(GLenum target) {
  GLuint id = 0;
  glGenTextures(1, &id);
  Texture t(id);
  t.target_ = target;
  glBindTexture(target, id);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // our texel rows are tightly packed
  return t;
}

Texture Texture::from_image(const Image& image, const TextureOptions& options) {
  if (image.empty()) throw Error("cannot make a texture from an empty image");
  Texture t = create_bound(GL_TEXTURE_2D);
  // Uploaded top row first, so t = 0 is the image's top; mesh uploads flip v to match.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  const GLint wrap = options.repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
  const GLint mag = options.linear ? GL_LINEAR : GL_NEAREST;
  const GLint min = options.mipmaps ? (options.linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST) : mag;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
  if (options.mipmaps) glGenerateMipmap(GL_TEXTURE_2D);
  t.width_ = image.width;
  t.height_ = image.height;
  t.mipmaps_ = options.mipmaps;
  return t;
}

void Texture::update(const Image& image) {
  if (target_ != GL_TEXTURE_2D) throw Error("Texture::update(): only 2D textures can be updated");
  if (image.empty()) throw Error("Texture::update(): empty image");
  glBindTexture(GL_TEXTURE_2D, id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (image.width != width_ || image.height != height_) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    width_ = image.width;
    height_ = image.height;
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  }
  if (mipmaps_) glGenerateMipmap(GL_TEXTURE_2D);
}

Texture Texture::stack_from_images(const std::vector<Image>& layers, GLenum target, const TextureOptions& options) {
  if (target != GL_TEXTURE_2D_ARRAY && target != GL_TEXTURE_3D) throw Error("stacked textures are 2D arrays or 3D");
  if (layers.empty() || layers[0].empty()) throw Error("cannot stack a texture from no layers");
  const int w = layers[0].width, h = layers[0].height;
  std::vector<uint8_t> texels;
  texels.reserve(size_t(w) * h * 4 * layers.size());
  for (const Image& layer : layers) {
    if (layer.width != w || layer.height != h) throw Error("stacked texture layers differ in size");
    texels.insert(texels.end(), layer.pixels.begin(), layer.pixels.end());
  }
  Texture t = create_bound(target);
  glTexImage3D(target, 0, GL_RGBA8, w, h, GLsizei(layers.size()), 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  const GLint wrap = options.repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glTexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, options.clamp_t ? GL_CLAMP_TO_EDGE : wrap);
  if (target == GL_TEXTURE_3D) glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);  // tone does not wrap
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, options.linear ? GL_LINEAR : GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, options.mipmaps ? GL_LINEAR_MIPMAP_LINEAR : (options.linear ? GL_LINEAR : GL_NEAREST));
  if (options.mipmaps) glGenerateMipmap(target);
  t.width_ = w;
  t.height_ = h;
  t.mipmaps_ = options.mipmaps;
  return t;
}

Texture Texture::lookup_row(const std::vector<glm::u8vec4>& texels, bool linear) {
  if (texels.empty()) throw Error("cannot make a lookup texture with no texels");
  Texture t = create_bound(GL_TEXTURE_2D);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, GLsizei(texels.size()), 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  const GLint filter = linear ? GL_LINEAR : GL_NEAREST;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  t.width_ = int(texels.size());
  t.height_ = 1;
  return t;
}

Texture Texture::depth_stencil(int width, int height) {
  Texture t = create_bound(GL_TEXTURE_2D);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, width, height, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, nullptr);
  // GLSL ES 3.00 reads a depth texture only when it is complete with nearest filtering.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  t.width_ = width;
  t.height_ = height;
  return t;
}

Texture Texture::data_rows(const std::vector<glm::vec4>& texels) {
  Texture t = create_bound(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);  // float textures filter on neither
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  t.update_rows(texels);
  return t;
}

void Texture::update_rows(const std::vector<glm::vec4>& texels) {
  const int rows = std::max(1, int((texels.size() + kDataTextureWidth - 1) / kDataTextureWidth));
  glBindTexture(GL_TEXTURE_2D, id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (rows > height_ || width_ != kDataTextureWidth) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kDataTextureWidth, rows, 0, GL_RGBA, GL_FLOAT, nullptr);
    width_ = kDataTextureWidth;
    height_ = rows;
  }
  const int full = int(texels.size()) / kDataTextureWidth, rest = int(texels.size()) % kDataTextureWidth;
  if (full > 0) glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kDataTextureWidth, full, GL_RGBA, GL_FLOAT, texels.data());
  if (rest > 0)
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, full, rest, 1, GL_RGBA, GL_FLOAT, texels.data() + size_t(full) * kDataTextureWidth);
}

void Texture::sample_level(int level) const {
  int levels = 1;
  while (mipmaps_ && (std::max(width_, height_) >> levels) > 0) ++levels;
  glBindTexture(target_, id());
  glTexParameteri(target_, GL_TEXTURE_BASE_LEVEL, std::clamp(level, 0, levels - 1));
  glTexParameteri(target_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
}

void Texture::set_filter(bool linear) const {
  glBindTexture(target_, id());
  glTexParameteri(target_, GL_TEXTURE_MIN_FILTER, linear ? GL_LINEAR : GL_NEAREST);
  glTexParameteri(target_, GL_TEXTURE_MAG_FILTER, linear ? GL_LINEAR : GL_NEAREST);
}

void Texture::bind(int unit) const {
  glActiveTexture(GLenum(GL_TEXTURE0 + unit));
  glBindTexture(target_, id());
}

const std::string& shader_source(const std::string& path) {
  static std::map<std::string, std::string> cache;  // string_view -> owned, once per path
  if (auto it = cache.find(path); it != cache.end()) return it->second;
  const auto& files = embedded_files();
  const auto found = files.find(path);
  if (found == files.end()) throw Error("Program: no embedded shader '" + path + "'");
  // A line `#include "common/x.glsl"` is replaced by that file: GLSL has no includes, and GLES
  // (WebGL2) links one shader object a stage, so code shared by several shaders is pasted in.
  std::string text(found->second), out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const std::string directive = "#include \"";
    if (line.rfind(directive, 0) == 0 && line.size() > directive.size() && line.back() == '"') {
      const std::string included = line.substr(directive.size(), line.size() - directive.size() - 1);
      if (included == path) throw Error("Program: shader '" + path + "' includes itself");
      out += shader_source(included) + "\n";
    } else {
      out += line + "\n";
    }
  }
  return cache.emplace(path, std::move(out)).first->second;
}

namespace {

GLenum stage_of(const std::string& name) {
  auto ends = [&](const char* ext) { return name.size() > 5 && name.ends_with(ext); };
  if (ends(".vert")) return GL_VERTEX_SHADER;
  if (ends(".frag")) return GL_FRAGMENT_SHADER;
  if (ends(".geom")) return GL_GEOMETRY_SHADER;
  if (ends(".comp")) return GL_COMPUTE_SHADER;
  throw Error("Program: cannot tell the stage of '" + name + "' (expected .vert, .frag, .geom or .comp)");
}

}  // namespace

const std::string& shader_header() {
  // Shader files carry no #version line: the target's is put first. Both say what GL 3.3 core
  // and WebGL2 (GLSL ES 3.00) share, so one file serves both (SPEC W5); ES wants precisions.
#ifdef __EMSCRIPTEN__
  static const std::string header = kWebGlShaderHeader;
#else
  static const std::string header = "#version 330 core\n";
#endif
  return header;
}

namespace {

// The target's header, the variant's defines, then the shader.
std::string with_header(const std::string& source, const std::vector<std::string>& defines) {
  std::string text = shader_header();
  for (const std::string& d : defines) text += "#define " + d + "\n";
  return text + source;
}

}  // namespace

Program Program::from_files(const std::vector<std::string>& stage_paths, const std::vector<std::string>& defines) {
  std::vector<std::pair<std::string, std::string>> named;
  for (const std::string& p : stage_paths) named.emplace_back(p, shader_source(p));
  return from_sources(named, defines);
}

Program Program::from_sources(const std::vector<std::pair<std::string, std::string>>& named_sources,
                              const std::vector<std::string>& defines) {
  Program program(glCreateProgram());
  std::vector<GLuint> shaders;
  auto cleanup = [&] {
    for (GLuint s : shaders) glDeleteShader(s);
  };
  for (const auto& [name, source] : named_sources) {
    const GLuint shader = glCreateShader(stage_of(name));
    shaders.push_back(shader);
    const std::string text = with_header(source, defines);
    const char* ptr = text.c_str();
    glShaderSource(shader, 1, &ptr, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[4096] = {};
      glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
      cleanup();
      throw Error("Program::compile(): " + name + ": " + log);
    }
    glAttachShader(program.id(), shader);
  }
  glLinkProgram(program.id());
  cleanup();
  GLint ok = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetProgramInfoLog(program.id(), sizeof(log), nullptr, log);
    throw Error(std::string("Program::link(): ") + log);
  }
  return program;
}

GLint Program::location(const char* name) const {
  auto it = locations_.find(name);
  if (it == locations_.end()) it = locations_.emplace(name, glGetUniformLocation(id(), name)).first;
  return it->second;
}

Renderbuffer Renderbuffer::create(GLenum format, int width, int height, int samples) {
  GLuint id = 0;
  glGenRenderbuffers(1, &id);
  glBindRenderbuffer(GL_RENDERBUFFER, id);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  return Renderbuffer(id);
}

Framebuffer Framebuffer::create() {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  return Framebuffer(id);
}

void Framebuffer::check_complete(const char* what) const {
  bind();
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error(std::string(what) + ": framebuffer incomplete (status 0x" + std::to_string(status) + ")");
}

}  // namespace inkwire::gl
