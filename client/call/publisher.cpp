#include "client/call/publisher.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <portaudio.h>

#include "client/call/audio_file.hpp"
#include "client/call/face_crop.hpp"
#include "client/call/voice_codec.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "common/log.hpp"
#include "common/video_source.hpp"

namespace inkwire {
namespace {

constexpr int kCropSide = kFaceVideoSide, kSearchWidth = kFaceSearchWidth, kPhotoSide = 480;
constexpr int kCropQuality = 75, kPhotoQuality = 90;

Image fit_within(const Image& image, int side_x, int side_y) {
  const double scale = std::min({1.0, double(side_x) / image.width, double(side_y) / image.height});
  if (scale >= 1.0) return image;
  return resized(image, std::max(1, int(std::lround(image.width * scale))), std::max(1, int(std::lround(image.height * scale))));
}

}  // namespace

// The voice source: a WAV file played in real time, or the default input device.
struct Publisher::Microphone {
  explicit Microphone(const std::string& spec, int frame_samples) : frame_(size_t(frame_samples)) {
    if (spec != "default") {
      samples_ = read_wav_mono(spec);
      return;
    }
    if (Pa_Initialize() != paNoError) throw Error("no microphone: PortAudio cannot start");
    // A constructor that throws runs no destructor: PortAudio is let go here on every refusal.
    const auto refuse = [&](const std::string& reason) {
      if (stream_) Pa_CloseStream(stream_);
      Pa_Terminate();
      throw Error("no microphone: " + reason);
    };
    if (Pa_GetDefaultInputDevice() == paNoDevice) refuse("this machine has no sound input device (give a WAV file instead)");
    const PaError e = Pa_OpenDefaultStream(&stream_, 1, 0, paFloat32, kCallRate, paFramesPerBufferUnspecified, nullptr, nullptr);
    if (e != paNoError) refuse(Pa_GetErrorText(e));
    if (const PaError started = Pa_StartStream(stream_); started != paNoError) refuse(Pa_GetErrorText(started));
    initialised_ = true;
  }
  ~Microphone() {
    if (stream_) Pa_CloseStream(stream_);
    if (initialised_) Pa_Terminate();
  }
  bool live() const { return stream_ != nullptr; }
  // The next frame, or nothing at the end of a file. A file's frames are paced by the caller.
  const std::vector<float>* next() {
    if (stream_) {
      const PaError e = Pa_ReadStream(stream_, frame_.data(), unsigned(frame_.size()));
      return e == paNoError || e == paInputOverflowed ? &frame_ : nullptr;
    }
    if (at_ >= samples_.size()) return nullptr;
    const size_t n = std::min(frame_.size(), samples_.size() - at_);
    std::fill(frame_.begin(), frame_.end(), 0.0f);
    std::copy_n(samples_.begin() + long(at_), n, frame_.begin());
    at_ += n;
    return &frame_;
  }

  std::vector<float> samples_, frame_;
  size_t at_ = 0;
  PaStream* stream_ = nullptr;
  bool initialised_ = false;
};

Publisher::Publisher(SessionClient& client, PublisherOptions options)
    : client_(client), options_(std::move(options)), start_(std::chrono::steady_clock::now()) {
  std::optional<Image> first;
  if (!options_.camera.empty()) {
    camera_source_ = std::make_unique<VideoSource>(options_.camera);
    first = camera_source_->next();
    if (!first) throw Error("camera '" + options_.camera + "' gives no picture");
  }
  if (!options_.microphone.empty())
    microphone_source_ = std::make_unique<Microphone>(options_.microphone, kCallRate * options_.voice_frame_ms / 1000);
  const Image photo = !options_.photo.empty() ? load_image(options_.photo) : first ? *first : Image();
  if (photo.width > 0) {
    photo_jpeg_ = encode_image(fit_within(photo, kPhotoSide, kPhotoSide), "jpg", kPhotoQuality);
    client_.send(protocol::NeutralPhoto{.jpeg = photo_jpeg_});
    bytes_ += photo_jpeg_.size();
  }
  camera_live_ = first.has_value();
  microphone_live_ = microphone_source_ != nullptr;
  // Where the clock its crops and voice are stamped with starts, in wall time: what a listener on
  // the same machine needs to measure mouth-to-ear (the browser engines' bench does).
  const auto since_start = std::chrono::steady_clock::now() - start_;
  const auto origin = std::chrono::system_clock::now() - std::chrono::duration_cast<std::chrono::system_clock::duration>(since_start);
  log_info("publishing", {{"camera", bool(camera_live_)}, {"microphone", bool(microphone_live_)},
                          {"clock_origin_unix_ms", std::chrono::duration<double, std::milli>(origin.time_since_epoch()).count()}});
  announce();
  if (first) camera_ = std::thread([this, frame = std::move(*first)] { run_camera(frame); });
  if (microphone_source_) microphone_ = std::thread([this] { run_microphone(); });
}

Publisher::~Publisher() {
  stopping_ = true;
  if (camera_.joinable()) camera_.join();
  if (microphone_.joinable()) microphone_.join();
}

uint32_t Publisher::now_ms() const {
  return uint32_t(std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start_).count());
}

void Publisher::announce() {
  client_.send(protocol::Publish{.camera = camera_live_ && !camera_off_, .microphone = microphone_live_ && !muted_});
}

void Publisher::say_again_if_rejoined() {
  uint64_t said = connection_said_;
  const uint64_t now = client_.connections();
  if (now == said || !client_.connected() || !connection_said_.compare_exchange_strong(said, now)) return;
  if (!photo_jpeg_.empty()) client_.send(protocol::NeutralPhoto{.jpeg = photo_jpeg_});
  announce();
  video_restart_ = true;
}

void Publisher::set_muted(bool muted) {
  muted_ = muted;
  announce();
}

void Publisher::set_camera_off(bool off) {
  camera_off_ = off;
  announce();
}

void Publisher::run_microphone() {
  VoiceEncoder encoder(options_.voice_frame_ms, options_.voice_bitrate);
  auto tick = std::chrono::steady_clock::now();
  while (!stopping_) {
    const std::vector<float>* frame = microphone_source_->next();
    if (!frame) break;
    say_again_if_rejoined();
    double sum = 0;
    for (float s : *frame) sum += double(s) * s;
    level_db_ = float(10.0 * std::log10(std::max(sum / double(frame->size()), 1e-10)));
    // Stamped with when its first sample was heard: a device's frame has just ended, a file's begins now.
    const uint32_t time = now_ms() - uint32_t(microphone_source_->live() ? options_.voice_frame_ms : 0);
    const std::vector<uint8_t> packet = encoder.encode(*frame);
    if (!muted_) {
      client_.send(protocol::VoiceFrame{.member = 0, .time_ms = time, .opus = packet});
      ++voices_;
      bytes_ += packet.size();
    }
    if (!microphone_source_->live()) std::this_thread::sleep_until(tick += std::chrono::milliseconds(options_.voice_frame_ms));
  }
  microphone_live_ = false;
  announce();
}

void Publisher::run_camera(Image frame) {
  // At most max_fps crops a second; a recorded source is played at its own rate, frames between
  // crops skipped, as a camera would have shown them.
  const double source_fps = camera_source_->fps() > 0 ? camera_source_->fps() : 25.0;
  const double fps = std::min(options_.max_fps, source_fps);
  const auto period = std::chrono::microseconds(int64_t(1e6 / fps));
  auto tick = std::chrono::steady_clock::now();
  int64_t read = 1;  // frames read from the source so far
  for (int64_t k = 1; !stopping_; ++k) {
    say_again_if_rejoined();
    if (!camera_off_) options_.crops == PublisherOptions::Crops::Vp8 ? send_video(frame) : send_crop(frame);
    std::optional<Image> next;
    if (camera_source_->live()) {
      next = camera_source_->next();
    } else {
      std::this_thread::sleep_until(tick += period);
      while (double(read) / source_fps <= double(k) / fps) {
        next = camera_source_->next();
        ++read;
        if (!next) break;
      }
    }
    if (!next) break;
    frame = std::move(*next);
  }
  camera_live_ = false;
  announce();
}

// The server's latest region of the face when it found one that lies in `frame`.
std::optional<protocol::FaceRegion> Publisher::usable_region(const Image& frame) const {
  const auto r = client_.face_region();
  if (r && r->found && r->width >= 8 && r->height >= 8 && r->x + r->width <= frame.width && r->y + r->height <= frame.height) return r;
  return std::nullopt;
}

void Publisher::send_crop(const Image& frame) {
  protocol::FaceCrop crop{.time_ms = now_ms(), .frame_width = uint16_t(frame.width), .frame_height = uint16_t(frame.height),
                          .x = 0, .y = 0, .width = uint16_t(frame.width), .height = uint16_t(frame.height), .jpeg = {}};
  Image picture;
  if (const auto region = usable_region(frame)) {
    crop.x = region->x, crop.y = region->y, crop.width = region->width, crop.height = region->height;
    picture = fit_within(cropped(frame, crop.x, crop.y, crop.width, crop.height), kCropSide, kCropSide);
  } else {
    picture = fit_within(frame, kSearchWidth, kSearchWidth);  // until the server finds the face
  }
  crop.jpeg = encode_image(picture, "jpg", kCropQuality);
  bytes_ += crop.jpeg.size();
  ++crops_;
  client_.send(std::move(crop));
}

// The face video's next frame: the crop follows the server's region (face_crop.hpp), scaled to
// 160 x 160; until the face is found, the whole frame scaled to at most 320 a side. A new picture size, a
// jump of the crop or the server's asking starts the video again with a key frame.
void Publisher::send_video(const Image& frame) {
  const uint64_t connection = client_.connections();
  bool key = client_.take_key_frame_request() || video_restart_.exchange(false);
  if (const auto reported = usable_region(frame)) {
    const FaceCropChoice choice = follow_face(video_crop_, *reported, frame.width, frame.height);
    video_crop_ = choice.region;
    key = key || choice.jumped;
  } else {
    video_crop_ = protocol::FaceRegion{.found = false, .x = 0, .y = 0, .width = uint16_t(frame.width), .height = uint16_t(frame.height)};
  }
  int width = kCropSide, height = kCropSide;
  if (!video_crop_.found) {  // the whole frame
    const PictureSize size = search_picture_size(frame.width, frame.height);
    width = size.width, height = size.height;
  }
  if (!video_encoder_ || video_encoder_->width() != width || video_encoder_->height() != height) {
    video_encoder_ = std::make_unique<FaceVideoEncoder>(width, height, options_.max_fps, options_.video_bitrate);
    key = true;
  }
  const Image picture = resized(cropped(frame, video_crop_.x, video_crop_.y, video_crop_.width, video_crop_.height), width, height);
  const uint32_t time = now_ms();
  FaceVideoEncoder::Frame encoded = video_encoder_->encode(picture, time, key);
  if (encoded.vp8.empty()) return;
  // Joined again while this frame was made: the server starts her stream afresh and would drop a
  // frame that is not a key frame, so the next one is.
  if (client_.connections() != connection && !encoded.key) {
    video_restart_ = true;
    return;
  }
  bytes_ += encoded.vp8.size();
  ++crops_;
  client_.send(protocol::FaceVideo{.time_ms = time, .sequence = ++video_sequence_, .frame_width = uint16_t(frame.width),
                                   .frame_height = uint16_t(frame.height), .x = video_crop_.x, .y = video_crop_.y, .width = video_crop_.width,
                                   .height = video_crop_.height, .key = encoded.key, .vp8 = std::move(encoded.vp8)});
}

}  // namespace inkwire
