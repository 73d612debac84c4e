#pragma once
// Where rendered frames go: one PNG, a numbered PNG series ("%04d" in the path) or an MP4
// (H.264 through the ffmpeg program, frames piped raw).
#include <cstdio>
#include <filesystem>
#include <string>

#include "common/image.hpp"

namespace inkwire {

class FrameWriter {
 public:
  // Throws inkwire::Error if the path cannot hold `frames` frames (e.g. one .png for many
  // frames without a %d pattern) or ffmpeg cannot be started.
  FrameWriter(const std::string& path, int frames, int fps, bool keep_alpha);
  ~FrameWriter();
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  void write(const Image& frame);
  // Finishes the file (waits for ffmpeg); throws inkwire::Error if the encoder failed.
  void close();

 private:
  std::string path_;
  bool video_ = false, keep_alpha_ = true;
  int fps_ = 24, written_ = 0;
  FILE* pipe_ = nullptr;
};

// Expands a printf-style frame pattern ("out/%04d.png") for frame `index`.
std::string frame_path(const std::string& pattern, int index);

}  // namespace inkwire
