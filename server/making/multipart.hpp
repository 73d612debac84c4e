#pragma once
// A multipart/form-data body (RFC 7578, as browsers send a FormData of files) read as it
// arrives, in pieces of any size, each part's bytes written straight to a file of its own in a
// folder: an upload never sits whole in the server's memory. The body comes from anyone: every
// part's head is bounded, file names are checked (a plain name, no folders, no dot files, each
// once), and a broken body is refused with the reason (tests/fuzz/fuzz_upload.cpp).
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace inkwire::server {

// The boundary a Content-Type of multipart/form-data names ("multipart/form-data;
// boundary=XYZ", quoted or not). Throws inkwire::Error when it is not one or names none.
std::string multipart_boundary(const std::string& content_type);

// Whether `name` may be a file of an upload: 1-128 letters, digits, spaces and . _ - ( ) +, not
// starting with a dot. Browsers send a picked file's own name, without its folders.
bool upload_file_name_allowed(const std::string& name);

class MultipartFiles {
 public:
  static constexpr size_t kMaxParts = 64;
  static constexpr size_t kMaxPartHead = 4096;

  // Parts are written into `folder`, which must exist and be empty.
  MultipartFiles(std::string boundary, std::filesystem::path folder);

  // The next bytes of the body. Throws inkwire::Error (with the reason) on a malformed body,
  // a part that is not a file, a name not allowed or given twice, more than kMaxParts parts.
  void feed(std::string_view bytes);
  // After the last byte: throws inkwire::Error unless the closing boundary came.
  void finish();

  // The files written, in the order they came.
  const std::vector<std::string>& files() const { return files_; }

 private:
  enum class State { Preamble, AfterBoundary, Head, Data, Done };
  void start_part(const std::string& head);
  void write(std::string_view bytes);

  std::string delimiter_;  // CRLF "--" boundary
  std::filesystem::path folder_;
  State state_ = State::Preamble;
  std::string pending_;  // bytes not yet known to be data rather than the start of a delimiter
  std::ofstream out_;
  std::vector<std::string> files_;
};

}  // namespace inkwire::server
