#pragma once
// Small libav helpers for the video encoder: owning pointers that free with the right libav call,
// and turning libav error codes into std::runtime_error with av_strerror's text.
#include <memory>
#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

namespace sdfreel {

// Throws std::runtime_error("video: WHAT: <libav message>") when ret < 0; returns ret otherwise.
int av_check(int ret, const std::string& what);
std::string av_error_text(int ret);

struct AvFrameFree {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct AvPacketFree {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct AvCodecContextFree {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct SwsContextFree {
  void operator()(SwsContext* c) const { sws_freeContext(c); }
};
// An output format context: closes its file (if open, and not a custom one) before freeing.
struct AvOutputContextFree {
  void operator()(AVFormatContext* c) const {
    if (c->pb && !(c->flags & AVFMT_FLAG_CUSTOM_IO) && !(c->oformat->flags & AVFMT_NOFILE))
      avio_closep(&c->pb);
    avformat_free_context(c);
  }
};

using AvFramePtr = std::unique_ptr<AVFrame, AvFrameFree>;
using AvPacketPtr = std::unique_ptr<AVPacket, AvPacketFree>;
using AvCodecContextPtr = std::unique_ptr<AVCodecContext, AvCodecContextFree>;
using SwsContextPtr = std::unique_ptr<SwsContext, SwsContextFree>;
using AvOutputContextPtr = std::unique_ptr<AVFormatContext, AvOutputContextFree>;

}  // namespace sdfreel
