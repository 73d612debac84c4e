#include "server/call/face_video_decoder.hpp"

#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavutil/imgutils.h>
#include <libswscale/swscale.h>
}

#include "common/av_reason.hpp"
#include "common/error.hpp"

namespace inkwire::server {

Vp8FrameHeader read_vp8_header(const protocol::Bytes& f) {
  if (f.size() < 3) throw Error("a VP8 frame of " + std::to_string(f.size()) + " bytes is too short");
  const uint32_t tag = uint32_t(f[0]) | uint32_t(f[1]) << 8 | uint32_t(f[2]) << 16;
  Vp8FrameHeader header{.key = (tag & 1) == 0};
  const unsigned version = (tag >> 1) & 7, shown = (tag >> 4) & 1, first_partition = tag >> 5;
  if (version > 3) throw Error("VP8 version " + std::to_string(version) + " is reserved");
  if (!shown) throw Error("a hidden VP8 frame (a face video shows every frame)");
  const size_t header_bytes = header.key ? 10 : 3;
  if (f.size() < header_bytes || first_partition > f.size() - header_bytes)
    throw Error("a VP8 frame's first partition (" + std::to_string(first_partition) + " bytes) runs past its end");
  if (!header.key) return header;
  if (f[3] != 0x9d || f[4] != 0x01 || f[5] != 0x2a) throw Error("a VP8 key frame without its start code");
  const unsigned w = unsigned(f[6]) | unsigned(f[7]) << 8, h = unsigned(f[8]) | unsigned(f[9]) << 8;
  if ((w >> 14) || (h >> 14)) throw Error("a scaled VP8 picture (a face video sends its pixels as they are)");
  header.width = int(w), header.height = int(h);
  if (header.width < 16 || header.height < 16 || header.width > protocol::kMaxVideoSide || header.height > protocol::kMaxVideoSide)
    throw Error("a face video of " + std::to_string(w) + " x " + std::to_string(h) + " px (16 to " + std::to_string(protocol::kMaxVideoSide) +
                " a side)");
  return header;
}

struct FaceVideoDecoder::Codec {
  AVCodecContext* context = nullptr;
  AVPacket* packet = nullptr;
  AVFrame* frame = nullptr;
  SwsContext* to_rgba = nullptr;

  Codec() {
    const AVCodec* vp8 = avcodec_find_decoder(AV_CODEC_ID_VP8);
    if (!vp8) throw Error("this libavcodec has no VP8 decoder");
    context = avcodec_alloc_context3(vp8);
    packet = av_packet_alloc();
    frame = av_frame_alloc();
    if (!context || !packet || !frame) throw Error("out of memory for a VP8 decoder");
    context->thread_count = 1;               // 160 px pictures: threads would cost more than they save
    context->err_recognition = AV_EF_EXPLODE; // a damaged frame is an error, not a concealed picture
    if (const int e = avcodec_open2(context, vp8, nullptr); e < 0) throw Error("cannot open the VP8 decoder: " + av_reason(e));
  }
  ~Codec() {
    sws_freeContext(to_rgba);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&context);
  }
};

FaceVideoDecoder::FaceVideoDecoder() = default;
FaceVideoDecoder::~FaceVideoDecoder() = default;

void FaceVideoDecoder::reset() {
  codec_.reset();
  sequence_.reset();
}

Image FaceVideoDecoder::decode(const protocol::FaceVideo& message) {
  try {
    const Vp8FrameHeader header = read_vp8_header(message.vp8);
    if (header.key != message.key) throw Error(message.key ? "a face video frame said key is no VP8 key frame" : "an unannounced VP8 key frame");
    if (header.key) {
      reset();  // a key frame starts the stream afresh, at any size within the limits
      width_ = header.width, height_ = header.height;
    } else if (!sequence_) {
      throw Error("face video before its key frame");
    } else if (message.sequence != *sequence_ + 1) {
      throw Error("face video frame " + std::to_string(*sequence_ + 1) + " is missing");
    }
    if (!codec_) codec_ = std::make_unique<Codec>();
    Codec& c = *codec_;
    // libavcodec reads up to AV_INPUT_BUFFER_PADDING_SIZE past the end: the packet owns a padded copy.
    if (const int e = av_new_packet(c.packet, int(message.vp8.size())); e < 0) throw Error("out of memory for a VP8 frame");
    std::copy(message.vp8.begin(), message.vp8.end(), c.packet->data);
    const int sent = avcodec_send_packet(c.context, c.packet);
    av_packet_unref(c.packet);
    if (sent < 0) throw Error("VP8 frame unreadable: " + av_reason(sent));
    if (const int e = avcodec_receive_frame(c.context, c.frame); e < 0) throw Error("VP8 frame gave no picture: " + av_reason(e));
    if (c.frame->width != width_ || c.frame->height != height_ || c.frame->format != AV_PIX_FMT_YUV420P) {
      av_frame_unref(c.frame);
      throw Error("a VP8 picture unlike its key frame's");
    }
    Image picture(width_, height_);
    c.to_rgba = sws_getCachedContext(c.to_rgba, width_, height_, AV_PIX_FMT_YUV420P, width_, height_, AV_PIX_FMT_RGBA, SWS_BILINEAR,
                                     nullptr, nullptr, nullptr);
    if (!c.to_rgba) throw Error("cannot convert a VP8 picture");
    uint8_t* rows[1] = {picture.pixels.data()};
    const int strides[1] = {width_ * 4};
    sws_scale(c.to_rgba, c.frame->data, c.frame->linesize, 0, height_, rows, strides);
    av_frame_unref(c.frame);
    sequence_ = message.sequence;
    return picture;
  } catch (const Error&) {
    reset();
    throw;
  }
}

}  // namespace inkwire::server
