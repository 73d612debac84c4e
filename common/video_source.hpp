#pragma once
// Frames from outside (SPEC F1, P9): a camera device, a video file, or an image sequence, read
// through OpenCV's VideoCapture and handed on as RGBA images. Every frame is checked: a source
// that cannot be opened, or frames of absurd size, end in a one-line inkwire::Error.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/image.hpp"

namespace cv {
class VideoCapture;
}

namespace inkwire {

class VideoSource {
 public:
  // `spec`: "camera:N" or "/dev/videoN" (a device), a folder (its image files in name order),
  // a printf pattern ("frames/%04d.png"), or a video file.
  explicit VideoSource(const std::string& spec);
  ~VideoSource();
  VideoSource(const VideoSource&) = delete;
  VideoSource& operator=(const VideoSource&) = delete;

  // The next frame, or nothing at the end of a file or sequence. Throws inkwire::Error when a
  // frame is unreadable or larger than kMaxImageSide.
  std::optional<Image> next();
  double fps() const { return fps_; }  // the source's, or 25 when it does not say
  bool live() const { return live_; }

 private:
  std::unique_ptr<cv::VideoCapture> capture_;
  std::vector<std::string> files_;  // a folder's images, read one by one
  size_t next_file_ = 0;
  double fps_ = 25.0;
  bool live_ = false;
  std::string spec_;
};

}  // namespace inkwire
