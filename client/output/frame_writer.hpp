#pragma once
// Where rendered frames go: one PNG, a numbered PNG series ("%04d" in the path) or an MP4
// (H.264 through the ffmpeg program, frames piped raw).
#include <cstdio>
#include <filesystem>
#include <string>

#include "common/image.hpp"

namespace inkwire {

// x264's settings for .mp4: CRF 20 "medium" looks clean; CRF 40 "veryslow" is the lowest
// sensible quality (the size video conferencing is compared with).
struct VideoQuality {
  int crf = 20;
  std::string preset = "medium";
};

class FrameWriter {
 public:
  // Throws inkwire::Error if the path cannot hold `frames` frames (e.g. one .png for many
  // frames without a %d pattern) or ffmpeg cannot be started.
  FrameWriter(const std::string& path, int frames, int fps, bool keep_alpha, VideoQuality quality = {});
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
  VideoQuality quality_;
  FILE* pipe_ = nullptr;
};

// Expands a printf-style frame pattern ("out/%04d.png") for frame `index`.
std::string frame_path(const std::string& pattern, int index);

}  // namespace inkwire
