#include "common/video_source.hpp"

#include <algorithm>
#include <filesystem>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "common/error.hpp"

namespace inkwire {

namespace {

bool is_image_file(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp" || ext == ".tif" || ext == ".tiff" || ext == ".pgm" || ext == ".ppm";
}

Image from_mat(const cv::Mat& mat, const std::string& spec) {
  if (mat.empty()) throw Error("video " + spec + ": empty frame");
  if (mat.cols > kMaxImageSide || mat.rows > kMaxImageSide) throw Error("video " + spec + ": frame larger than " + std::to_string(kMaxImageSide) + " pixels");
  cv::Mat rgba;
  switch (mat.channels()) {
    case 1: cv::cvtColor(mat, rgba, cv::COLOR_GRAY2RGBA); break;
    case 3: cv::cvtColor(mat, rgba, cv::COLOR_BGR2RGBA); break;
    case 4: cv::cvtColor(mat, rgba, cv::COLOR_BGRA2RGBA); break;
    default: throw Error("video " + spec + ": frames with " + std::to_string(mat.channels()) + " channels");
  }
  if (rgba.depth() != CV_8U) rgba.convertTo(rgba, CV_8U);
  Image image(rgba.cols, rgba.rows);
  for (int y = 0; y < rgba.rows; ++y) std::copy_n(rgba.ptr<uint8_t>(y), size_t(rgba.cols) * 4, image.at(0, y));
  return image;
}

}  // namespace

VideoSource::VideoSource(const std::string& spec) : spec_(spec) {
  std::error_code ec;
  int device = -1;
  if (spec.rfind("camera:", 0) == 0) {
    const std::string n = spec.substr(7);
    if (n.empty() || n.size() > 3 || !std::all_of(n.begin(), n.end(), ::isdigit)) throw Error("video '" + spec + "': camera:N needs a device number");
    device = std::stoi(n);
  } else if (spec.rfind("/dev/video", 0) == 0 && spec.size() > 10 && spec.size() < 14 && std::all_of(spec.begin() + 10, spec.end(), ::isdigit)) {
    device = std::stoi(spec.substr(10));
  }
  if (device >= 0) {
    capture_ = std::make_unique<cv::VideoCapture>(device, cv::CAP_V4L2);
    if (!capture_->isOpened()) throw Error("video '" + spec + "': no camera device " + std::to_string(device) + " can be opened");
    live_ = true;
  } else if (std::filesystem::is_directory(spec, ec)) {
    for (const auto& entry : std::filesystem::directory_iterator(spec, ec))
      if (entry.is_regular_file() && is_image_file(entry.path())) files_.push_back(entry.path().string());
    std::sort(files_.begin(), files_.end());
    if (files_.empty()) throw Error("video '" + spec + "': the folder holds no image files");
  } else {
    if (spec.find('%') == std::string::npos && !std::filesystem::is_regular_file(spec, ec)) throw Error("video '" + spec + "': no such file");
    // FFmpeg for files, OpenCV's own reader for patterns: no GStreamer pipeline guessing.
    capture_ = std::make_unique<cv::VideoCapture>(spec, spec.find('%') != std::string::npos ? cv::CAP_IMAGES : cv::CAP_FFMPEG);
    if (!capture_->isOpened()) throw Error("video '" + spec + "': not a video or image sequence OpenCV can read");
  }
  if (capture_) {
    const double fps = capture_->get(cv::CAP_PROP_FPS);
    if (fps >= 1.0 && fps <= 240.0) fps_ = fps;
  }
}

VideoSource::~VideoSource() = default;

std::optional<Image> VideoSource::next() {
  cv::Mat mat;
  if (!capture_) {
    if (next_file_ >= files_.size()) return std::nullopt;
    return load_image(files_[next_file_++]);  // size and format checks of the image reader
  }
  try {
    if (!capture_->read(mat) || mat.empty()) return std::nullopt;
  } catch (const cv::Exception& e) {
    throw Error("video '" + spec_ + "': unreadable frame: " + e.msg);
  }
  return from_mat(mat, spec_);
}

}  // namespace inkwire
