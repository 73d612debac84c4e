#include "server/making/upload_import.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "common/error.hpp"
#include "common/glb_mesh.hpp"
#include "common/model_bundle.hpp"
#include "common/model_files.hpp"

namespace inkwire::server {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// What a model refers to and no reader opens as a model by itself.
bool companion(const std::string& name) {
  static const char* kinds[] = {".bin", ".mtl", ".png", ".jpg", ".jpeg", ".bmp", ".tga", ".gif", ".tif", ".tiff", ".webp", ".ktx", ".ktx2", ".dds",
                                ".hdr", ".exr", ".psd", ".txt", ".md", ".json"};
  const std::string ext = lower(fs::path(name).extension().string());
  return std::find(std::begin(kinds), std::end(kinds), ext) != std::end(kinds);
}

// A texture's pixels from its header alone: a picture claiming 60 000 x 60 000 is refused before
// anything decodes it (a decompression bomb).
uint64_t picture_pixels(const std::vector<unsigned char>& bytes) {
  // The reader by the bytes' own signature (what a client decodes them as), not by a name:
  // glTF's textures are PNG or JPEG.
  const bool png = bytes.size() > 8 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' && bytes[3] == 'G';
  const bool jpeg = bytes.size() > 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
  if (!png && !jpeg) throw Error("a texture of the model is neither PNG nor JPEG");
  auto input = OIIO::ImageInput::create(png ? "png" : "jpeg");
  OIIO::Filesystem::IOMemReader reader(const_cast<unsigned char*>(bytes.data()), bytes.size());
  OIIO::ImageSpec spec;
  if (!input || !input->set_ioproxy(&reader) || !input->open(png ? "texture.png" : "texture.jpg", spec))
    throw Error("a texture of the model is not a picture this server reads (" + (input ? input->geterror() : OIIO::geterror()) + ")");
  return uint64_t(std::max(spec.width, 0)) * uint64_t(std::max(spec.height, 0));
}

std::vector<uint8_t> read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error("cannot read " + file.filename().string());
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

std::string upload_model_file(const std::vector<std::string>& files) {
  std::vector<std::string> models;
  for (const std::string& f : files)
    if (!companion(f)) models.push_back(f);
  if (models.empty()) throw Error("no model among the files uploaded (a .bin, .mtl or picture goes with its model: upload them together)");
  if (models.size() > 1) throw Error("several models in one upload (" + models[0] + ", " + models[1] + "): upload one with its files");
  return models.front();
}

namespace {

// `reason` with the upload's folder taken out of the paths it names: the sender knows its files
// by their names.
std::string without_folder(std::string reason, const fs::path& folder) {
  for (const std::string& prefix : {(folder / "").string(), (fs::absolute(folder) / "").string()})
    for (size_t at; (at = reason.find(prefix)) != std::string::npos;) reason.erase(at, prefix.size());
  return reason;
}

ImportedModel import_files(const fs::path& folder, const ImportLimits& limits);

}  // namespace

ImportedModel import_upload(const fs::path& folder, const ImportLimits& limits) {
  try {
    return import_files(folder, limits);
  } catch (const Error& e) {
    throw Error(without_folder(e.what(), folder));
  }
}

namespace {

ImportedModel import_files(const fs::path& folder, const ImportLimits& limits) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (entry.is_regular_file(ec)) files.push_back(entry.path().filename().string());
  if (ec) throw Error("cannot read the upload's folder: " + ec.message());
  std::sort(files.begin(), files.end());
  const fs::path model = folder / upload_model_file(files);
  ImportedModel out;
  // Made whole as a configured scene's model is (an OBJ with its .mtl and textures, a glTF with
  // its .bin: one GLB); a GLB already whole travels as it came.
  std::optional<SelfContainedModel> whole;
  try {
    whole = self_contained_model(model);
  } catch (const Error& e) {
    const std::string outside = refused_model_file();
    if (!outside.empty()) throw Error(model.filename().string() + " refers to a file outside its upload (" + outside + ")");
    throw;
  }
  out.name = whole ? whole->name : model.stem().string() + ".glb";
  out.glb = whole ? std::move(whole->bytes) : read_bytes(model);
  const std::string outside = refused_model_file();
  if (!outside.empty()) throw Error(model.filename().string() + " refers to a file outside its upload (" + outside + ")");
  // Read as every client will read it (the browser's own reader): what it cannot draw is refused here.
  const Mesh mesh = read_glb_mesh(out.glb, model.filename().string());
  out.triangles = mesh.triangles.size();
  if (out.triangles > limits.max_triangles)
    throw Error(model.filename().string() + " has " + std::to_string(out.triangles) + " triangles; this server takes at most " + std::to_string(limits.max_triangles));
  for (const Material& m : mesh.materials)
    if (!m.texture_bytes.empty()) out.texture_pixels += picture_pixels(m.texture_bytes);
  if (out.texture_pixels > limits.max_texture_pixels)
    throw Error(model.filename().string() + "'s textures hold " + std::to_string(out.texture_pixels) + " pixels; this server takes at most " +
                std::to_string(limits.max_texture_pixels));
  return out;
}

}  // namespace
}  // namespace inkwire::server
