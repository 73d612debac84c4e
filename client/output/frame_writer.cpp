#include "client/output/frame_writer.hpp"

#include <regex>

#include "common/error.hpp"

namespace inkwire {
namespace {

bool has_pattern(const std::string& path) { return std::regex_search(path, std::regex("%0?[0-9]*d")); }

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

std::string frame_path(const std::string& pattern, int index) {
  std::smatch m;
  if (!std::regex_search(pattern, m, std::regex("%(0?)([0-9]*)d"))) return pattern;
  const int width = m[2].length() ? std::stoi(m[2]) : 0;
  std::string number = std::to_string(index);
  if (m[1].length() && int(number.size()) < width) number.insert(0, size_t(width) - number.size(), '0');
  return m.prefix().str() + number + m.suffix().str();
}

FrameWriter::FrameWriter(const std::string& path, int frames, int fps, bool keep_alpha, VideoQuality quality)
    : path_(path), keep_alpha_(keep_alpha), fps_(fps), quality_(std::move(quality)) {
  video_ = path.ends_with(".mp4");
  if (!video_ && frames > 1 && !has_pattern(path))
    throw Error("--out '" + path + "' names one image but " + std::to_string(frames) + " frames were asked for: use a %04d pattern or .mp4");
  if (const auto dir = std::filesystem::path(path).parent_path(); !dir.empty()) std::filesystem::create_directories(dir);
}

FrameWriter::~FrameWriter() {
  if (pipe_) pclose(pipe_);
}

void FrameWriter::write(const Image& frame) {
  if (!video_) {
    save_image(frame, frame_path(path_, written_++), keep_alpha_);
    return;
  }
  if (!pipe_) {
    const std::string cmd = "ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgba -s " + std::to_string(frame.width) + "x" +
                            std::to_string(frame.height) + " -r " + std::to_string(fps_) +
                            " -i - -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -c:v libx264 -preset " + shell_quote(quality_.preset) +
                            " -crf " + std::to_string(quality_.crf) + " -pix_fmt yuv420p -movflags +faststart " +
                            shell_quote(path_);
    pipe_ = popen(cmd.c_str(), "w");
    if (!pipe_) throw Error("could not start ffmpeg to write " + path_);
  }
  if (std::fwrite(frame.pixels.data(), 1, frame.pixels.size(), pipe_) != frame.pixels.size())
    throw Error("ffmpeg stopped accepting frames for " + path_);
  ++written_;
}

void FrameWriter::close() {
  if (!pipe_) return;
  const int status = pclose(pipe_);
  pipe_ = nullptr;
  if (status != 0) throw Error("ffmpeg failed writing " + path_ + " (is the ffmpeg package installed?)");
}

}  // namespace inkwire
