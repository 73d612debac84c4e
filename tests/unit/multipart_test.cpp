// An upload's multipart body as the server reads it (server/making/multipart.hpp): files written
// whole whatever pieces the body comes in, hostile names and broken bodies refused with the
// reason, and the model picked among an upload's files.
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "server/making/multipart.hpp"
#include "server/making/upload_import.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::server;
namespace fs = std::filesystem;

namespace {

std::string part(const std::string& filename, const std::string& data) {
  return "--B0undary\r\nContent-Disposition: form-data; name=\"file\"; filename=\"" + filename + "\"\r\nContent-Type: application/octet-stream\r\n\r\n" +
         data + "\r\n";
}
const std::string kEnd = "--B0undary--\r\n";

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The files of `body` fed `piece` bytes at a time, or the reason it was refused.
std::string parse(const std::string& body, size_t piece, std::vector<std::string>* names = nullptr, fs::path* folder_out = nullptr) {
  const fs::path folder = test::scratch_dir() / ("parts-" + std::to_string(piece));
  fs::remove_all(folder);
  fs::create_directories(folder);
  if (folder_out) *folder_out = folder;
  return test::error_of([&] {
    MultipartFiles files("B0undary", folder);
    for (size_t at = 0; at < body.size(); at += piece) files.feed(std::string_view(body).substr(at, piece));
    files.finish();
    if (names) *names = files.files();
  });
}

}  // namespace

TEST(MultipartTest, FilesComeOutWholeInPiecesOfAnySize) {
  // Data that holds what a delimiter starts with, a CR LF, and bytes of every value.
  std::string binary;
  for (int i = 0; i < 256; ++i) binary += char(i);
  binary += "\r\n--B0undar\r\n-";
  const std::string body = "preamble\r\n" + part("truck.gltf", "{\"asset\": {}}") + part("truck0.bin", binary) + kEnd + "epilogue";
  for (size_t piece : {size_t(1), size_t(2), size_t(7), size_t(13), size_t(4096)}) {
    std::vector<std::string> names;
    fs::path folder;
    ASSERT_EQ(parse(body, piece, &names, &folder), "") << piece;
    EXPECT_EQ(names, (std::vector<std::string>{"truck.gltf", "truck0.bin"}));
    EXPECT_EQ(read(folder / "truck.gltf"), "{\"asset\": {}}") << piece;
    EXPECT_EQ(read(folder / "truck0.bin"), binary) << piece;
  }
}

TEST(MultipartTest, HostileNamesAndBrokenBodiesAreRefusedWithTheReason) {
  std::vector<std::string> names;
  EXPECT_EQ(parse(part("../../outside.obj", "x") + kEnd, 5, &names), "") << "a path's folders are dropped";
  EXPECT_EQ(names, std::vector<std::string>{"outside.obj"});
  EXPECT_NE(parse(part(".hidden", "x") + kEnd, 5).find("not allowed"), std::string::npos);
  EXPECT_NE(parse(part("a;b.obj", "x") + kEnd, 5).find("not allowed"), std::string::npos);
  EXPECT_NE(parse(part("a.obj", "x") + part("a.obj", "y") + kEnd, 5).find("twice"), std::string::npos);
  EXPECT_NE(parse(part("a.obj", "x"), 5).find("closing boundary"), std::string::npos) << "cut short";
  EXPECT_NE(parse(kEnd, 5).find("no file"), std::string::npos);
  EXPECT_NE(parse("--B0undary\r\nContent-Disposition: form-data; name=\"title\"\r\n\r\nhello\r\n" + kEnd, 5).find("not a file"), std::string::npos);
  EXPECT_NE(parse("--B0undary\r\n" + std::string(5000, 'h'), 100).find("4 KiB"), std::string::npos) << "a part's head is bounded";
  std::string many;
  for (int i = 0; i < 65; ++i) many += part("f" + std::to_string(i) + ".png", "x");
  EXPECT_NE(parse(many + kEnd, 4096).find("at most 64"), std::string::npos);
}

TEST(MultipartTest, TheBoundaryComesFromTheContentType) {
  EXPECT_EQ(multipart_boundary("multipart/form-data; boundary=----WebKitFormBoundaryab12"), "----WebKitFormBoundaryab12");
  EXPECT_EQ(multipart_boundary("multipart/form-data; boundary=\"quoted one\""), "quoted one");
  EXPECT_NE(test::error_of([] { multipart_boundary("application/json"); }).find("multipart/form-data"), std::string::npos);
  EXPECT_NE(test::error_of([] { multipart_boundary("multipart/form-data"); }).find("boundary"), std::string::npos);
  EXPECT_NE(test::error_of([] { multipart_boundary("multipart/form-data; boundary=" + std::string(71, 'b')); }).find("boundary"), std::string::npos);
}

TEST(MultipartTest, TheModelIsTheOneFileNoOtherGoesWith) {
  EXPECT_EQ(upload_model_file({"Truck.gltf", "Truck0.bin", "Truck.png"}), "Truck.gltf");
  EXPECT_EQ(upload_model_file({"jeep.mtl", "jeep.obj", "jeep.jpg"}), "jeep.obj");
  EXPECT_NE(test::error_of([] { upload_model_file({"a.png", "b.bin"}); }).find("no model"), std::string::npos);
  EXPECT_NE(test::error_of([] { upload_model_file({"a.obj", "b.ply"}); }).find("several models"), std::string::npos);
}
