#include "client/call/face_video_encoder.hpp"

#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "common/av_reason.hpp"
#include "common/error.hpp"

namespace inkwire {

struct FaceVideoEncoder::Codec {
  AVCodecContext* context = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* to_yuv = nullptr;

  ~Codec() {
    sws_freeContext(to_yuv);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&context);
  }
};

FaceVideoEncoder::FaceVideoEncoder(int width, int height, double fps, int bitrate) : codec_(std::make_unique<Codec>()), width_(width), height_(height) {
  av_log_set_level(AV_LOG_ERROR);  // libvpx says its version on stderr for every encoder otherwise
  const AVCodec* vpx = avcodec_find_encoder_by_name("libvpx");
  if (!vpx) throw Error("this libavcodec has no libvpx VP8 encoder");
  Codec& c = *codec_;
  c.context = avcodec_alloc_context3(vpx);
  c.frame = av_frame_alloc();
  c.packet = av_packet_alloc();
  if (!c.context || !c.frame || !c.packet) throw Error("out of memory for a VP8 encoder");
  c.context->width = width, c.context->height = height;
  c.context->pix_fmt = AV_PIX_FMT_YUV420P;
  c.context->time_base = AVRational{1, 1000};  // frames are stamped in milliseconds
  c.context->framerate = AVRational{int(fps * 1000), 1000};
  c.context->bit_rate = bitrate;
  c.context->gop_size = 600;  // key frames when asked for, else one in 40 s at 15 a second
  c.context->thread_count = 1;
  c.context->qmin = 4, c.context->qmax = 56;
  // Real time, nothing held back: every packet is the frame just given, shown (no alt-ref).
  av_opt_set(c.context->priv_data, "deadline", "realtime", 0);
  av_opt_set_int(c.context->priv_data, "cpu-used", 8, 0);
  av_opt_set_int(c.context->priv_data, "lag-in-frames", 0, 0);
  av_opt_set_int(c.context->priv_data, "auto-alt-ref", 0, 0);
  if (const int e = avcodec_open2(c.context, vpx, nullptr); e < 0) throw Error("cannot open the VP8 encoder: " + av_reason(e));
  c.frame->format = AV_PIX_FMT_YUV420P, c.frame->width = width, c.frame->height = height;
  if (av_frame_get_buffer(c.frame, 0) < 0) throw Error("out of memory for a VP8 picture");
  c.to_yuv = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P, SWS_BILINEAR, nullptr, nullptr, nullptr);
  if (!c.to_yuv) throw Error("cannot convert pictures for VP8");
}

FaceVideoEncoder::~FaceVideoEncoder() = default;

FaceVideoEncoder::Frame FaceVideoEncoder::encode(const Image& picture, uint32_t time_ms, bool key) {
  if (picture.width != width_ || picture.height != height_)
    throw Error("a " + std::to_string(picture.width) + " x " + std::to_string(picture.height) + " picture for a " + std::to_string(width_) + " x " +
                std::to_string(height_) + " face video");
  Codec& c = *codec_;
  if (av_frame_make_writable(c.frame) < 0) throw Error("out of memory for a VP8 picture");
  const uint8_t* rows[1] = {picture.pixels.data()};
  const int strides[1] = {width_ * 4};
  sws_scale(c.to_yuv, rows, strides, 0, height_, c.frame->data, c.frame->linesize);
  c.frame->pts = time_ms;
  c.frame->pict_type = key ? AV_PICTURE_TYPE_I : AV_PICTURE_TYPE_NONE;  // libvpx forces a key frame for I
  if (const int e = avcodec_send_frame(c.context, c.frame); e < 0) throw Error("VP8 encoding failed: " + av_reason(e));
  Frame out;
  while (avcodec_receive_packet(c.context, c.packet) == 0) {
    out.vp8.assign(c.packet->data, c.packet->data + c.packet->size);  // lag 0: one packet per frame
    out.key = (c.packet->flags & AV_PKT_FLAG_KEY) != 0;
    av_packet_unref(c.packet);
  }
  return out;
}

}  // namespace inkwire
