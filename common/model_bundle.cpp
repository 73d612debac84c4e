#include "common/model_bundle.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <map>
#include <set>

#include <assimp/DefaultIOSystem.h>
#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "common/mesh_import.hpp"
#include "common/model_files.hpp"

namespace inkwire {
namespace {

namespace fs = std::filesystem;

// The file system as assimp sees it, noting every file it opens: what a model "follows".
class RecordingIOSystem final : public ModelIOSystem {
 public:
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    Assimp::IOStream* stream = ModelIOSystem::Open(file, mode);
    if (stream) opened.insert(fs::weakly_canonical(file));
    return stream;
  }
  std::set<fs::path> opened;
};

std::vector<uint8_t> read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read '" + path.string() + "'");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The format hint assimp and glTF know an image by: its extension, lower case, at most 3 letters.
std::string format_hint(const fs::path& image) {
  std::string ext = image.extension().string();
  ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == "jpeg" ? "jpg" : ext.substr(0, 3);
}

// How a material names the scene's n-th embedded texture: "*n".
std::string embedded_name(unsigned n) {
  std::string name = std::to_string(n);
  name.insert(name.begin(), '*');
  return name;
}

// Every texture of every material that names a file: the file read into the scene and the
// material pointed at it ("*N"), so the exporter writes it into the GLB.
std::vector<fs::path> embed_textures(aiScene& scene, const fs::path& model) {
  std::vector<fs::path> files;
  std::map<fs::path, unsigned> embedded_as;  // a file several materials use goes in once
  std::vector<aiTexture*> textures(scene.mTextures, scene.mTextures + scene.mNumTextures);
  for (unsigned m = 0; m < scene.mNumMaterials; ++m) {
    aiMaterial& material = *scene.mMaterials[m];
    for (int t = aiTextureType_NONE; t <= AI_TEXTURE_TYPE_MAX; ++t) {
      const auto type = aiTextureType(t);
      for (unsigned i = 0; i < material.GetTextureCount(type); ++i) {
        aiString ref;
        if (material.GetTexture(type, i, &ref) != AI_SUCCESS || ref.length == 0 || ref.data[0] == '*') continue;
        const std::optional<fs::path> found = find_texture_file(model, ref.C_Str());
        if (!found) throw Error(model.string() + ": its texture '" + ref.C_Str() + "' is missing");
        if (const auto known = embedded_as.find(*found); known != embedded_as.end()) {
          const aiString embedded(embedded_name(known->second).c_str());
          material.AddProperty(&embedded, AI_MATKEY_TEXTURE(type, i));
          continue;
        }
        const std::vector<uint8_t> bytes = read_file(*found);
        auto texture = std::make_unique<aiTexture>();
        texture->mWidth = unsigned(bytes.size());  // compressed: the byte count, height 0
        texture->mHeight = 0;
        texture->pcData = new aiTexel[(bytes.size() + sizeof(aiTexel) - 1) / sizeof(aiTexel)];
        std::memcpy(texture->pcData, bytes.data(), bytes.size());
        std::snprintf(texture->achFormatHint, sizeof texture->achFormatHint, "%s", format_hint(*found).c_str());
        texture->mFilename = found->filename().string();
        const aiString embedded(embedded_name(unsigned(textures.size())).c_str());
        material.AddProperty(&embedded, AI_MATKEY_TEXTURE(type, i));
        embedded_as[*found] = unsigned(textures.size());
        textures.push_back(texture.release());
        files.push_back(*found);
      }
    }
  }
  if (textures.size() != scene.mNumTextures) {
    delete[] scene.mTextures;  // the array only; its textures live on in `textures`
    scene.mTextures = new aiTexture*[textures.size()];
    std::copy(textures.begin(), textures.end(), scene.mTextures);
    scene.mNumTextures = unsigned(textures.size());
  }
  return files;
}

// The colour of each material as a client reads it (base colour, else diffuse: older formats
// have only the latter, else the loader's default), in the scene's order.
std::vector<aiColor4D> material_colours(const aiScene& scene) {
  std::vector<aiColor4D> colours;
  const glm::vec4 fallback = Material{}.base_colour;
  for (unsigned m = 0; m < scene.mNumMaterials; ++m) {
    aiColor4D colour(fallback.r, fallback.g, fallback.b, fallback.a);
    if (scene.mMaterials[m]->Get(AI_MATKEY_BASE_COLOR, colour) != AI_SUCCESS) scene.mMaterials[m]->Get(AI_MATKEY_COLOR_DIFFUSE, colour);
    colours.push_back(colour);
  }
  return colours;
}

// A GLB: a 12-byte header ("glTF", version 2, length), then a JSON chunk (length, "JSON", text),
// then the binary chunk; little-endian throughout.
constexpr uint32_t kGlbMagic = 0x46546C67u, kGlbVersion = 2, kJsonChunk = 0x4E4F534Au;

uint32_t read_u32(const std::vector<uint8_t>& b, size_t at) {
  return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24;
}
void append_u32(std::vector<uint8_t>& b, uint32_t v) {
  for (int i = 0; i < 4; ++i) b.push_back(uint8_t(v >> (8 * i)));
}

// assimp's GLB writer drops a textured material's colour factor and adds a specular-glossiness
// extension that readers then prefer: the factor is written back and the extension removed, so
// the GLB draws as the model did.
std::vector<uint8_t> with_material_colours(const std::vector<uint8_t>& glb, const std::vector<aiColor4D>& colours) {
  if (glb.size() < 20 || read_u32(glb, 0) != kGlbMagic || read_u32(glb, 16) != kJsonChunk)
    throw Error("the GLB writer made no GLB");
  const uint32_t json_length = read_u32(glb, 12);
  if (20 + size_t(json_length) > glb.size()) throw Error("the GLB writer made a truncated GLB");
  nlohmann::json gltf = nlohmann::json::parse(glb.begin() + 20, glb.begin() + 20 + json_length);
  if (gltf.contains("materials")) {
    auto& materials = gltf["materials"];
    for (size_t m = 0; m < materials.size() && m < colours.size(); ++m) {
      const aiColor4D& c = colours[m];
      materials[m]["pbrMetallicRoughness"]["baseColorFactor"] = {c.r, c.g, c.b, c.a};
      if (materials[m].contains("extensions")) materials[m]["extensions"].erase("KHR_materials_pbrSpecularGlossiness");
    }
  }
  for (const char* list : {"extensionsUsed", "extensionsRequired"})
    if (gltf.contains(list)) {
      auto& names = gltf[list];
      names.erase(std::remove(names.begin(), names.end(), "KHR_materials_pbrSpecularGlossiness"), names.end());
    }
  std::string json = gltf.dump();
  json.resize((json.size() + 3) / 4 * 4, ' ');  // chunks are 4-byte aligned, JSON padded with spaces
  std::vector<uint8_t> out;
  const std::vector<uint8_t> rest(glb.begin() + 20 + json_length, glb.end());  // the binary chunk
  append_u32(out, kGlbMagic);
  append_u32(out, kGlbVersion);
  append_u32(out, uint32_t(12 + 8 + json.size() + rest.size()));
  append_u32(out, uint32_t(json.size()));
  append_u32(out, kJsonChunk);
  out.insert(out.end(), json.begin(), json.end());
  out.insert(out.end(), rest.begin(), rest.end());
  return out;
}

bool is_glb(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".glb";
}

}  // namespace

std::optional<SelfContainedModel> self_contained_model(const fs::path& file, UpAxis up) {
  load_mesh(file, nullptr, up);  // refuses what no client could draw, with the reason
  const UpAxis own = file_up_axis(file);
  if (up == UpAxis::Auto) up = own;
  Assimp::Importer importer;
  auto* io = new RecordingIOSystem;  // the importer owns it
  importer.SetIOHandler(io);
  // Vertices equal in every attribute become one, so a format of shared vertices (OFF, PLY) keeps
  // its size as indexed triangles.
  if (!importer.ReadFile(file.string(), aiProcess_JoinIdenticalVertices)) throw Error(file.string() + ": " + importer.GetErrorString());
  std::unique_ptr<aiScene> scene(importer.GetOrphanedScene());
  std::vector<fs::path> gathered;
  const fs::path self = fs::weakly_canonical(file);
  for (const fs::path& opened : io->opened)
    if (opened != self) gathered.push_back(opened);
  const std::vector<fs::path> textures = embed_textures(*scene, file);
  gathered.insert(gathered.end(), textures.begin(), textures.end());
  // A reader of the file finds its own up axis; a model told otherwise is turned upright here,
  // so the GLB (Y-up by definition) needs no telling. A GLB whole and upright already travels as
  // it is; every other model becomes one, so every client reads one format (the browser's module
  // reads GLB alone, common/glb_mesh.hpp).
  if (gathered.empty() && up == own && is_glb(file)) return std::nullopt;
  const glm::mat4 turn = upright_transform(file, up);
  aiMatrix4x4 upright;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) upright[row][column] = turn[column][row];  // glm is column-major
  scene->mRootNode->mTransformation = upright * scene->mRootNode->mTransformation;

  const std::vector<aiColor4D> colours = material_colours(*scene);
  Assimp::Exporter exporter;
  const aiExportDataBlob* blob = exporter.ExportToBlob(scene.get(), "glb2");
  if (!blob || !blob->data || blob->size == 0)
    throw Error(file.string() + ": cannot be made into one GLB file: " + exporter.GetErrorString());
  const auto* data = static_cast<const uint8_t*>(blob->data);
  std::vector<uint8_t> glb;
  try {
    glb = with_material_colours({data, data + blob->size}, colours);
  } catch (const std::exception& e) {
    throw Error(file.string() + ": cannot be made into one GLB file: " + e.what());
  }
  return SelfContainedModel{.name = file.stem().string() + ".glb", .bytes = std::move(glb), .gathered = std::move(gathered)};
}

}  // namespace inkwire
