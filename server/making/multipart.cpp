#include "server/making/multipart.hpp"

#include <algorithm>
#include <cctype>

#include "common/error.hpp"

namespace inkwire::server {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// The value of parameter `name` in a header value (`form-data; name="file"; filename="a.obj"`),
// unquoted; empty when absent.
std::string parameter(const std::string& value, const std::string& name) {
  const std::string low = lower(value);
  size_t at = 0;
  while ((at = low.find(name + "=", at)) != std::string::npos) {
    const bool starts = at == 0 || low[at - 1] == ';' || low[at - 1] == ' ';
    at += name.size() + 1;
    if (!starts) continue;
    if (at < value.size() && value[at] == '"') {
      const size_t end = value.find('"', at + 1);
      if (end == std::string::npos) throw Error("a part's " + name + " has no closing quote");
      return value.substr(at + 1, end - at - 1);
    }
    return value.substr(at, value.find(';', at) - at);
  }
  return "";
}

}  // namespace

std::string multipart_boundary(const std::string& content_type) {
  if (lower(content_type).rfind("multipart/form-data", 0) != 0) throw Error("an upload is sent as multipart/form-data");
  const std::string boundary = parameter(content_type, "boundary");
  // RFC 2046: 1-70 characters from a small set, not ending in a space.
  if (boundary.empty() || boundary.size() > 70 || boundary.back() == ' ' ||
      boundary.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789'()+_,-./:=? ") != std::string::npos)
    throw Error("the upload's multipart boundary is missing or malformed");
  return boundary;
}

bool upload_file_name_allowed(const std::string& name) {
  return !name.empty() && name.size() <= 128 && name[0] != '.' &&
         name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 ._-()+") == std::string::npos;
}

MultipartFiles::MultipartFiles(std::string boundary, std::filesystem::path folder)
    : delimiter_("\r\n--" + boundary), folder_(std::move(folder)), pending_("\r\n") {}  // the first boundary needs no CRLF before it

void MultipartFiles::start_part(const std::string& head) {
  std::string disposition;
  size_t at = 0;
  while (at < head.size()) {
    const size_t end = std::min(head.find("\r\n", at), head.size());
    const std::string line = head.substr(at, end - at);
    at = end + 2;
    const size_t colon = line.find(':');
    if (colon == std::string::npos) throw Error("a part's head line is not NAME: VALUE");
    if (lower(line.substr(0, colon)) == "content-disposition") disposition = line.substr(colon + 1);
  }
  if (lower(disposition).find("form-data") == std::string::npos) throw Error("a part is not form-data");
  std::string name = parameter(disposition, "filename");
  if (name.empty()) throw Error("a part of the upload is not a file");
  // Some browsers send a path: only the file's own name counts.
  name = name.substr(name.find_last_of("/\\") == std::string::npos ? 0 : name.find_last_of("/\\") + 1);
  if (!upload_file_name_allowed(name)) throw Error("file name '" + name.substr(0, 64) + "' is not allowed (letters, digits, spaces, . _ - ( ) +)");
  if (std::find(files_.begin(), files_.end(), name) != files_.end()) throw Error("file '" + name + "' comes twice");
  if (files_.size() >= kMaxParts) throw Error("an upload holds at most " + std::to_string(kMaxParts) + " files");
  files_.push_back(name);
  out_ = std::ofstream(folder_ / name, std::ios::binary | std::ios::trunc);
  if (!out_) throw Error("cannot write the upload's file " + name);
}

void MultipartFiles::write(std::string_view bytes) {
  out_.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out_) throw Error("cannot write the upload's file " + files_.back());
}

void MultipartFiles::feed(std::string_view bytes) {
  pending_.append(bytes);
  for (;;) {
    switch (state_) {
      case State::Preamble:
      case State::Data: {
        const size_t found = pending_.find(delimiter_);
        if (found == std::string::npos) {
          // All but what could be the start of a delimiter is data (or preamble, dropped).
          const size_t keep = std::min(pending_.size(), delimiter_.size() - 1);
          if (state_ == State::Data) write(std::string_view(pending_).substr(0, pending_.size() - keep));
          pending_.erase(0, pending_.size() - keep);
          return;
        }
        if (state_ == State::Data) {
          write(std::string_view(pending_).substr(0, found));
          out_.close();
          if (!out_) throw Error("cannot write the upload's file " + files_.back());
        }
        pending_.erase(0, found + delimiter_.size());
        state_ = State::AfterBoundary;
        break;
      }
      case State::AfterBoundary:
        if (pending_.size() < 2) return;
        if (pending_.compare(0, 2, "--") == 0) {
          state_ = State::Done;
          pending_.clear();
          return;
        }
        if (pending_.compare(0, 2, "\r\n") != 0) throw Error("the upload's body is malformed after a boundary");
        pending_.erase(0, 2);
        state_ = State::Head;
        break;
      case State::Head: {
        const size_t end = pending_.find("\r\n\r\n");
        if (end == std::string::npos) {
          if (pending_.size() > kMaxPartHead) throw Error("a part's head is over 4 KiB");
          return;
        }
        if (end > kMaxPartHead) throw Error("a part's head is over 4 KiB");
        start_part(pending_.substr(0, end));
        pending_.erase(0, end + 4);
        state_ = State::Data;
        break;
      }
      case State::Done:
        pending_.clear();  // the epilogue is ignored
        return;
    }
  }
}

void MultipartFiles::finish() {
  if (state_ != State::Done) throw Error(files_.empty() ? "the upload holds no file" : "the upload ended before its closing boundary");
  if (files_.empty()) throw Error("the upload holds no file");
}

}  // namespace inkwire::server
