#include "common/mesh_import.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <sstream>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/metadata.h>
#include <assimp/scene.h>
#include <glm/mat4x4.hpp>

#include "common/model_files.hpp"
#include "common/error.hpp"
#include "common/mesh_welder.hpp"

namespace inkwire {
namespace {

// Nodes deeper than this are refused: real scenes are shallow, hostile ones recurse.
constexpr int kMaxNodeDepth = 256;

glm::mat4 to_glm(const aiMatrix4x4& m) {
  // assimp is row-major, glm column-major.
  return glm::mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4, m.c4, m.d4);
}

std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

// `path` itself, else the file in its folder whose name differs only in letter case.
std::optional<std::filesystem::path> existing_file_any_case(const std::filesystem::path& path) {
  if (std::filesystem::is_regular_file(path)) return path;
  std::error_code error;
  const std::string wanted = lower_case(path.filename().string());
  for (const auto& entry : std::filesystem::directory_iterator(path.parent_path(), error))
    if (entry.is_regular_file(error) && lower_case(entry.path().filename().string()) == wanted) return entry.path();
  return std::nullopt;
}

}  // namespace

std::optional<std::filesystem::path> find_texture_file(const std::filesystem::path& model, const std::string& ref) {
  if (ref.empty() || ref[0] == '*') return std::nullopt;
  // Files written on Windows name textures with backslashes (".\jeep1.jpg"), from a root
  // that means the model's own folder ("\..\LWO\earth.jpg"), in any letter case, or with the
  // author's own folders ("C:\models\tex.png"): read the name as written, relative to the
  // model, else the file of that name beside the model (where its texture travels with it).
  std::string portable = ref;
  std::replace(portable.begin(), portable.end(), '\\', '/');
  portable.erase(0, portable.find_first_not_of('/'));
  const std::filesystem::path folder = model.parent_path();
  for (const std::filesystem::path& path : {folder / portable, folder / std::filesystem::path(portable).filename()})
    if (std::optional<std::filesystem::path> found = existing_file_any_case(path.lexically_normal()); found && model_file_allowed(*found)) return found;
  return std::nullopt;
}

namespace {

class MeshBuilder {
 public:
  MeshBuilder(const aiScene& scene, const std::filesystem::path& file, ImportReport& report)
      : scene_(scene), file_(file), report_(report) {
    read_materials();
  }

  void add_node(const aiNode& node, const glm::mat4& parent, int depth) {
    if (depth > kMaxNodeDepth) throw Error("scene nodes nest deeper than " + std::to_string(kMaxNodeDepth));
    if (!visited_.insert(&node).second) throw Error("scene node graph has a cycle");
    const glm::mat4 transform = parent * to_glm(node.mTransformation);
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
      if (node.mMeshes[i] >= scene_.mNumMeshes) throw Error("scene node refers to a mesh that does not exist");
      add_mesh(*scene_.mMeshes[node.mMeshes[i]], transform);
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) {
      if (!node.mChildren[i]) throw Error("scene node has a missing child");
      add_node(*node.mChildren[i], transform, depth + 1);
    }
  }

  Mesh take() { return welder_.take(); }

 private:
  void read_materials() {
    for (unsigned m = 0; m < scene_.mNumMaterials; ++m) {
      const aiMaterial* src = scene_.mMaterials[m];
      Material mat;
      aiString name;
      if (src->Get(AI_MATKEY_NAME, name) == AI_SUCCESS) mat.name = name.C_Str();
      aiColor4D colour;
      if (src->Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS || src->Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS)
        mat.base_colour = {colour.r, colour.g, colour.b, colour.a};
      aiString tex;
      if (src->GetTexture(aiTextureType_BASE_COLOR, 0, &tex) == AI_SUCCESS ||
          src->GetTexture(aiTextureType_DIFFUSE, 0, &tex) == AI_SUCCESS)
        attach_texture(mat, tex.C_Str());
      welder_.materials().push_back(std::move(mat));
    }
    if (welder_.materials().empty()) welder_.materials().emplace_back();
  }

  void attach_texture(Material& mat, const std::string& ref) {
    if (const aiTexture* embedded = scene_.GetEmbeddedTexture(ref.c_str())) {
      if (embedded->mHeight == 0) {  // compressed (PNG, JPEG...): mWidth is the byte count
        const auto* bytes = reinterpret_cast<const unsigned char*>(embedded->pcData);
        mat.texture_bytes.assign(bytes, bytes + embedded->mWidth);
      }
      return;  // uncompressed embedded texels are rare; such materials render untextured
    }
    if (const std::optional<std::filesystem::path> found = find_texture_file(file_, ref)) mat.texture_file = *found;
  }

  void add_mesh(const aiMesh& src, const glm::mat4& transform) {
    report_.source_vertices += src.mNumVertices;
    if (!src.mVertices && src.mNumVertices > 0) throw Error("mesh '" + std::string(src.mName.C_Str()) + "' has no positions");
    if (src.mMaterialIndex >= welder_.materials().size()) throw Error("mesh refers to a material that does not exist");
    std::vector<uint32_t> welded(src.mNumVertices);
    for (unsigned v = 0; v < src.mNumVertices; ++v) {
      const aiVector3D& a = src.mVertices[v];
      const glm::vec3 p = glm::vec3(transform * glm::vec4(a.x, a.y, a.z, 1.0f));
      welded[v] = welder_.weld(p);
      if (src.mColors[0]) {
        const aiColor4D& c = src.mColors[0][v];
        welder_.set_colour(welded[v], {c.r, c.g, c.b, c.a});
      }
    }
    const bool has_uv = src.mTextureCoords[0] != nullptr;
    for (unsigned f = 0; f < src.mNumFaces; ++f) {
      const aiFace& face = src.mFaces[f];
      if (face.mNumIndices != 3) {
        ++report_.non_triangles_skipped;
        continue;
      }
      std::array<uint32_t, 3> tri{};
      std::array<glm::vec2, 3> uv{};
      for (int c = 0; c < 3; ++c) {
        const unsigned i = face.mIndices[c];
        if (i >= src.mNumVertices)
          throw Error("face " + std::to_string(f) + " refers to vertex " + std::to_string(i) + " but the mesh has only " +
                      std::to_string(src.mNumVertices));
        tri[c] = welded[i];
        if (has_uv) uv[c] = {src.mTextureCoords[0][i].x, src.mTextureCoords[0][i].y};
      }
      welder_.add_triangle(tri, uv, has_uv, src.mMaterialIndex);
    }
  }

  const aiScene& scene_;
  std::filesystem::path file_;
  ImportReport& report_;
  MeshWelder welder_;
  std::unordered_set<const aiNode*> visited_;
};

// Formats that declare their element counts up front (OFF, PLY) can make assimp reserve or
// loop over billions of elements before noticing the file is short. A vertex or face takes at
// least a few bytes even in binary, so counts the file is too small to hold are refused here.
void check_declared_counts(const std::filesystem::path& file, uintmax_t bytes) {
  std::ifstream in(file, std::ios::binary);
  std::string first;
  in >> first;
  unsigned long long vertices = 0, faces = 0;
  if (first == "OFF" || first == "COFF" || first == "NOFF" || first == "CNOFF") {
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line) && (line.empty() || line[0] == '#')) {}
    std::istringstream counts(line);
    counts >> vertices >> faces;
  } else if (first == "ply") {
    std::string line;
    for (int i = 0; i < 200 && std::getline(in, line) && line.rfind("end_header", 0) != 0; ++i) {
      std::istringstream words(line);
      std::string element, name;
      unsigned long long n = 0;
      if (words >> element >> name >> n && element == "element") (name == "vertex" ? vertices : faces) += n;
    }
  } else {
    return;
  }
  constexpr unsigned long long kMinBytesPerElement = 3;  // e.g. "0 0 0" squeezed, or 3 bytes binary
  if (vertices > kMaxMeshVertices || faces > kMaxMeshTriangles ||
      (vertices + faces) * kMinBytesPerElement > bytes)
    throw Error(file.string() + ": header declares " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
                " faces, more than the " + std::to_string(bytes) + "-byte file can hold or than the limits allow");
}

// assimp reports some damage only through its log while still returning a scene: faces with
// out-of-range indices dropped, vertices that do not fit the primitive mode dropped, a missing
// material replaced. We refuse such files rather than draw part of them, so the import listens
// to the log and keeps the first error or data-loss warning of the current thread's import.
thread_local std::string* current_import_problem = nullptr;

class ProblemCollector final : public Assimp::LogStream {
 public:
  void write(const char* message) override {
    if (!current_import_problem || !current_import_problem->empty()) return;
    std::string m = message;
    const bool error = m.rfind("Error", 0) == 0;
    const bool data_lost = m.find("dropped") != std::string::npos || m.find("out-of-range") != std::string::npos;
    if (!error && !data_lost) return;
    if (const auto colon = m.find(": "); colon != std::string::npos) m = m.substr(colon + 2);
    while (!m.empty() && (m.back() == '\n' || m.back() == ' ')) m.pop_back();
    *current_import_problem = m;
  }
};

void listen_to_assimp() {
  static std::once_flag once;
  std::call_once(once, [] {
    Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
    Assimp::DefaultLogger::get()->attachStream(new ProblemCollector, Assimp::Logger::Err | Assimp::Logger::Warn);
  });
}

}  // namespace

UpAxis parse_up_axis(const std::string& text) {
  if (text == "auto") return UpAxis::Auto;
  if (text == "y" || text == "Y") return UpAxis::Y;
  if (text == "z" || text == "Z") return UpAxis::Z;
  throw Error("up axis '" + text + "' is not auto, y or z");
}

const char* to_string(UpAxis up) { return up == UpAxis::Z ? "z" : up == UpAxis::Y ? "y" : "auto"; }

namespace {

// 3D Studio files are Z-up by convention, and assimp turns them Y-up as it reads them.
bool z_up_format_assimp_turns(const std::filesystem::path& file) { return lower_case(file.extension().string()) == ".3ds"; }

UpAxis scene_up_axis(const aiScene& scene, const std::filesystem::path& file) {
  int32_t axis = 0;
  if (scene.mMetaData && scene.mMetaData->Get("UpAxis", axis)) return axis == 2 ? UpAxis::Z : UpAxis::Y;
  return z_up_format_assimp_turns(file) ? UpAxis::Z : UpAxis::Y;
}

glm::mat4 upright(const std::filesystem::path& file, UpAxis up) {
  const glm::mat4 z_to_y(1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1);  // (x, y, z) -> (x, z, -y)
  if (!z_up_format_assimp_turns(file)) return up == UpAxis::Z ? z_to_y : glm::mat4(1.0f);
  // Read by assimp, the file's Z is already +Y and its Y is -Z.
  return up == UpAxis::Y ? glm::transpose(z_to_y) : glm::mat4(1.0f);  // (x, y, z) -> (x, -z, y)
}

}  // namespace

UpAxis file_up_axis(const std::filesystem::path& file) {
  if (lower_case(file.extension().string()) != ".fbx") return z_up_format_assimp_turns(file) ? UpAxis::Z : UpAxis::Y;
  Assimp::Importer importer;
  importer.SetIOHandler(new ModelIOSystem);  // the importer owns it
  const aiScene* scene = importer.ReadFile(file.string(), 0);
  return scene ? scene_up_axis(*scene, file) : UpAxis::Y;
}

glm::mat4 upright_transform(const std::filesystem::path& file, UpAxis up) {
  return upright(file, up == UpAxis::Auto ? file_up_axis(file) : up);
}

Mesh load_mesh(const std::filesystem::path& file, ImportReport* report_out, UpAxis up) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) throw Error(file.string() + ": is a folder, not a model file");
  if (!std::filesystem::is_regular_file(file, ec)) throw Error(file.string() + ": no such file");
  const uintmax_t bytes = std::filesystem::file_size(file, ec);
  if (ec) throw Error(file.string() + ": cannot read file size");
  if (bytes == 0) throw Error(file.string() + ": file is empty");
  if (bytes > kMaxMeshFileBytes) throw Error(file.string() + ": file is larger than the 1 GiB limit");

  check_declared_counts(file, bytes);

  Assimp::Importer importer;
  importer.SetIOHandler(new ModelIOSystem);  // the importer owns it
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const unsigned flags = aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure;
  const aiScene* scene = nullptr;
  std::string problem;
  listen_to_assimp();
  current_import_problem = &problem;
  try {
    scene = importer.ReadFile(file.string(), flags);
  } catch (const std::exception& e) {  // assimp mostly reports through GetErrorString, not always
    current_import_problem = nullptr;
    throw Error(file.string() + ": " + e.what());
  }
  current_import_problem = nullptr;
  if (!scene) throw Error(file.string() + ": " + importer.GetErrorString());
  if (!problem.empty()) throw Error(file.string() + ": " + problem);
  if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) throw Error(file.string() + ": file is incomplete");
  if (!scene->mRootNode) throw Error(file.string() + ": file has no scene graph");

  ImportReport report;
  Mesh mesh;
  try {
    MeshBuilder builder(*scene, file, report);
    builder.add_node(*scene->mRootNode, upright(file, up == UpAxis::Auto ? scene_up_axis(*scene, file) : up), 0);
    mesh = builder.take();
    report.degenerate_dropped = remove_degenerate_and_unused(mesh);
    validate_mesh(mesh);
  } catch (const Error& e) {
    throw Error(file.string() + ": " + e.what());
  }
  if (report_out) *report_out = report;
  return mesh;
}

}  // namespace inkwire
