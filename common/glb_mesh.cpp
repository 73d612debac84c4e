#include "common/glb_mesh.hpp"

#include <cstring>
#include <fstream>
#include <functional>
#include <optional>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

// tinygltf (Debian's libtinygltf-dev): the JSON through nlohmann-json; no file system (a GLB from
// the wire refers to nothing outside itself) and no image decoding here (textures keep their
// encoded bytes, decoded where every other texture is).
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
#define TINYGLTF_NO_INCLUDE_JSON
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "common/error.hpp"
#include "common/mesh_welder.hpp"

namespace inkwire {
namespace {

constexpr int kMaxNodeDepth = 256;  // as common/mesh_import: real scenes are shallow

// Keeps an image's encoded bytes (PNG, JPEG) as they are. `model` is the model being read: tinygltf
// hands over an image's buffer view without checking that it lies inside its buffer.
bool keep_encoded(tinygltf::Image* image, const int, std::string* error, std::string*, int, int, const unsigned char* bytes, int size,
                  void* model) {
  if (image->bufferView >= 0) {
    const auto& m = *static_cast<const tinygltf::Model*>(model);
    const tinygltf::BufferView& view = m.bufferViews.at(size_t(image->bufferView));  // tinygltf checked the index
    const size_t buffer_size = m.buffers.at(size_t(view.buffer)).data.size();
    if (size < 0 || view.byteOffset > buffer_size || view.byteLength > buffer_size - view.byteOffset) {
      if (error) *error += "an image reaches past its buffer\n";
      return false;
    }
  }
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

// An accessor's bytes, checked to lie inside its buffer: `count` elements `stride` bytes apart,
// each of `element_bytes`; `accessor` the accessor itself.
struct AccessorBytes {
  const tinygltf::Accessor& accessor;
  const unsigned char* data;
  size_t stride, count;
};
AccessorBytes accessor_bytes(const tinygltf::Model& model, int index, const char* what) {
  const std::string name(what);
  if (index < 0 || size_t(index) >= model.accessors.size()) throw Error(name + " in an accessor that does not exist");
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  if (a.sparse.isSparse) throw Error(name + " in a sparse accessor, which is not read");
  if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size()) throw Error(name + " without their buffer view");
  const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) throw Error(name + " in a buffer view without its buffer");
  const std::vector<unsigned char>& buffer = model.buffers[size_t(view.buffer)].data;
  const int components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  const int component_bytes = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  if (components <= 0 || component_bytes <= 0) throw Error(name + " of an unknown type");
  const size_t element_bytes = size_t(components) * size_t(component_bytes);
  const size_t stride = view.byteStride ? view.byteStride : element_bytes;
  if (stride < element_bytes || view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset ||
      a.byteOffset > view.byteLength ||
      (a.count > 0 && (a.count - 1 > (view.byteLength - a.byteOffset) / stride ||
                       (a.count - 1) * stride + element_bytes > view.byteLength - a.byteOffset)))
    throw Error(name + " reach past their buffer");
  return {a, buffer.data() + view.byteOffset + a.byteOffset, stride, a.count};
}

// An accessor's elements as floats (normalised integers scaled to 0..1): at least `components`
// floats per element.
class FloatReader {
 public:
  FloatReader(const tinygltf::Model& model, int accessor_index, int components, const char* what)
      : bytes_(accessor_bytes(model, accessor_index, what)) {
    const tinygltf::Accessor& a = bytes_.accessor;
    components_ = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (components_ < components || components_ > 4) throw Error(std::string(what) + " of the wrong type");
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !a.normalized) throw Error(std::string(what) + " of integers that are not normalised");
    component_bytes_ = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)));
  }
  size_t count() const { return bytes_.count; }
  int components() const { return components_; }
  float at(size_t element, int component) const {
    const unsigned char* p = bytes_.data + element * bytes_.stride + size_t(component) * component_bytes_;
    switch (bytes_.accessor.componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); return f; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return float(*p) / 255.0f;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p, 2); return float(v) / 65535.0f; }
      case TINYGLTF_COMPONENT_TYPE_BYTE: return std::max(float(int8_t(*p)) / 127.0f, -1.0f);
      case TINYGLTF_COMPONENT_TYPE_SHORT: { int16_t v; std::memcpy(&v, p, 2); return std::max(float(v) / 32767.0f, -1.0f); }
      default: throw Error("an attribute of an unknown component type");
    }
  }

 private:
  AccessorBytes bytes_;
  int components_ = 0;
  size_t component_bytes_ = 0;
};

std::vector<uint32_t> read_indices(const tinygltf::Model& model, int accessor_index, size_t vertex_count) {
  std::vector<uint32_t> indices;
  if (accessor_index < 0) {  // none: the vertices in order
    for (size_t i = 0; i < vertex_count; ++i) indices.push_back(uint32_t(i));
    return indices;
  }
  const AccessorBytes bytes = accessor_bytes(model, accessor_index, "indices");
  const int size = tinygltf::GetComponentSizeInBytes(uint32_t(bytes.accessor.componentType));
  if (bytes.accessor.type != TINYGLTF_TYPE_SCALAR || (size != 1 && size != 2 && size != 4)) throw Error("indices that are not whole numbers");
  for (size_t i = 0; i < bytes.count; ++i) {
    uint32_t v = 0;
    std::memcpy(&v, bytes.data + i * bytes.stride, size_t(size));  // little-endian
    if (v >= vertex_count) throw Error("an index past the vertices");
    indices.push_back(v);
  }
  return indices;
}

glm::mat4 node_transform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = float(node.matrix[size_t(i)]);  // column-major, as glm
    return m;
  }
  glm::mat4 m(1.0f);
  if (node.translation.size() == 3) m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4)
    m *= glm::mat4_cast(glm::quat(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]), float(node.rotation[2])));
  if (node.scale.size() == 3) m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

class GlbMeshBuilder {
 public:
  explicit GlbMeshBuilder(const tinygltf::Model& model) : model_(model) {
    for (const tinygltf::Material& source : model.materials) {
      Material m;
      m.name = source.name;
      const auto& factor = source.pbrMetallicRoughness.baseColorFactor;
      if (factor.size() == 4) m.base_colour = {factor[0], factor[1], factor[2], factor[3]};
      const int texture = source.pbrMetallicRoughness.baseColorTexture.index;
      if (texture >= 0 && size_t(texture) < model.textures.size()) {
        const int image = model.textures[size_t(texture)].source;
        if (image >= 0 && size_t(image) < model.images.size()) m.texture_bytes = model.images[size_t(image)].image;
      }
      welder_.materials().push_back(std::move(m));
    }
  }

  void add_node(int index, const glm::mat4& parent, int depth) {
    if (index < 0 || size_t(index) >= model_.nodes.size()) throw Error("a node that does not exist");
    if (depth > kMaxNodeDepth) throw Error("nodes nest deeper than " + std::to_string(kMaxNodeDepth));
    if (visiting_.size() <= size_t(index)) visiting_.resize(model_.nodes.size());
    if (visiting_[size_t(index)]) throw Error("the node graph has a cycle");
    visiting_[size_t(index)] = true;
    const tinygltf::Node& node = model_.nodes[size_t(index)];
    const glm::mat4 transform = parent * node_transform(node);
    if (node.mesh >= 0) {
      if (size_t(node.mesh) >= model_.meshes.size()) throw Error("a node's mesh does not exist");
      for (const tinygltf::Primitive& p : model_.meshes[size_t(node.mesh)].primitives) add_primitive(p, transform);
    }
    for (int child : node.children) add_node(child, transform, depth + 1);
    visiting_[size_t(index)] = false;
  }

  Mesh take() {
    // assimp's glTF reader always adds a default material (white) after the file's own, for
    // primitives that name none: so does this one.
    welder_.materials().push_back(Material{.base_colour = glm::vec4(1.0f)});
    return welder_.take();
  }

 private:
  void add_primitive(const tinygltf::Primitive& p, const glm::mat4& transform) {
    if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP && p.mode != TINYGLTF_MODE_TRIANGLE_FAN)
      return;  // points and lines: no renderer draws them
    const auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) throw Error("a primitive without positions");
    const FloatReader positions(model_, position->second, 3, "positions");
    if (positions.count() > kMaxMeshVertices) throw Error("more vertices than the limit");
    std::optional<FloatReader> colours, uvs;
    if (auto c = p.attributes.find("COLOR_0"); c != p.attributes.end()) colours.emplace(model_, c->second, 3, "colours");
    if (auto t = p.attributes.find("TEXCOORD_0"); t != p.attributes.end()) uvs.emplace(model_, t->second, 2, "texture coordinates");
    if ((colours && colours->count() != positions.count()) || (uvs && uvs->count() != positions.count()))
      throw Error("attributes of different lengths");
    uint32_t material = uint32_t(model_.materials.size());
    if (p.material >= 0 && size_t(p.material) < model_.materials.size()) material = uint32_t(p.material);

    std::vector<uint32_t> welded(positions.count());
    for (size_t v = 0; v < positions.count(); ++v) {
      const glm::vec3 local(positions.at(v, 0), positions.at(v, 1), positions.at(v, 2));
      welded[v] = welder_.weld(glm::vec3(transform * glm::vec4(local, 1.0f)));
      if (colours)
        welder_.set_colour(welded[v], {colours->at(v, 0), colours->at(v, 1), colours->at(v, 2), colours->components() == 4 ? colours->at(v, 3) : 1.0f});
    }
    const std::vector<uint32_t> indices = read_indices(model_, p.indices, positions.count());
    const auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
      if (welder_triangles_ >= kMaxMeshTriangles) throw Error("more triangles than the limit");
      ++welder_triangles_;
      std::array<glm::vec2, 3> corner_uvs{};
      const uint32_t corners[3] = {a, b, c};
      // glTF's v runs down the image; the native reader (assimp) turns it to run up.
      if (uvs)
        for (int k = 0; k < 3; ++k) corner_uvs[size_t(k)] = {uvs->at(corners[k], 0), 1.0f - uvs->at(corners[k], 1)};
      welder_.add_triangle({welded[a], welded[b], welded[c]}, corner_uvs, uvs.has_value(), material);
    };
    if (p.mode == TINYGLTF_MODE_TRIANGLES) {
      for (size_t i = 0; i + 2 < indices.size(); i += 3) add(indices[i], indices[i + 1], indices[i + 2]);
    } else if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (size_t i = 0; i + 2 < indices.size(); ++i)
        i % 2 ? add(indices[i + 1], indices[i], indices[i + 2]) : add(indices[i], indices[i + 1], indices[i + 2]);
    } else {
      for (size_t i = 1; i + 1 < indices.size(); ++i) add(indices[0], indices[i], indices[i + 1]);
    }
  }

  const tinygltf::Model& model_;
  MeshWelder welder_;
  std::vector<bool> visiting_;
  size_t welder_triangles_ = 0;
};

}  // namespace

Mesh read_glb_mesh(std::span<const uint8_t> bytes, const std::string& name) {
  if (bytes.empty()) throw Error(name + ": the model is empty");
  if (bytes.size() > (size_t(1) << 30)) throw Error(name + ": the model is larger than the 1 GiB limit");
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  loader.SetImageLoader(&keep_encoded, &model);
  std::string error, warning;
  bool ok = false;
  try {
    ok = loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), unsigned(bytes.size()));
  } catch (const std::exception& e) {
    throw Error(name + ": not a GLB model: " + e.what());
  }
  if (!ok) {
    const size_t line = error.find('\n');
    throw Error(name + ": not a GLB model: " + (error.empty() ? "unreadable" : error.substr(0, line)));
  }
  Mesh mesh;
  try {
    GlbMeshBuilder builder(model);
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (size_t(scene) < model.scenes.size()) {
      for (int node : model.scenes[size_t(scene)].nodes) builder.add_node(node, glm::mat4(1.0f), 0);
    } else {
      throw Error("the model has no scene");
    }
    mesh = builder.take();
    remove_degenerate_and_unused(mesh);
    validate_mesh(mesh);
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
  return mesh;
}

}  // namespace inkwire
