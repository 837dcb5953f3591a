#include "plugins/video_av/av_codecs.h"

extern "C" {
#include <libavutil/cpu.h>
#include <libavutil/opt.h>
}

namespace sdfreel {
namespace {

void set_private_option(AVCodecContext* ctx, const char* key, const std::string& value) {
  av_check(av_opt_set(ctx->priv_data, key, value.c_str(), 0),
           std::string("setting ") + ctx->codec->name + " option " + key + "=" + value);
}

}  // namespace

void configure_video_codec(const VideoCodecSpec& spec, AVCodecContext* ctx, int width, int height,
                           AVRational fps, int crf) {
  ctx->width = width;
  ctx->height = height;
  ctx->sample_aspect_ratio = AVRational{1, 1};
  ctx->framerate = fps;
  ctx->time_base = av_inv_q(fps);  // pts = frame index
  ctx->pix_fmt = spec.pix_fmt;
  ctx->flags |= AV_CODEC_FLAG_BITEXACT;  // no version strings that change between builds
  ctx->thread_count = spec.threads;

  // The display pixels are BT.709 primaries; Y'CbCr codecs use the BT.709 matrix in tv range
  // (what players assume for HD), RGB codecs store full range.
  ctx->color_primaries = AVCOL_PRI_BT709;
  ctx->color_trc = AVCOL_TRC_BT709;
  ctx->colorspace = !spec.yuv ? AVCOL_SPC_RGB : spec.bt601 ? AVCOL_SPC_BT470BG : AVCOL_SPC_BT709;
  ctx->color_range = spec.yuv ? AVCOL_RANGE_MPEG : AVCOL_RANGE_JPEG;

  const std::string encoder = spec.encoder;
  if (encoder == "libx264") {
    set_private_option(ctx, "preset", "medium");
    set_private_option(ctx, "crf", std::to_string(crf));
    // x264 r3095's AVX-512 code reads memory it never wrote (in mbtree): two encodes in one
    // process then differ with whatever the heap held before. Its AVX2 code gives the same bytes
    // without that, and every AVX-512 CPU has AVX2.
    if (av_get_cpu_flags() & AV_CPU_FLAG_AVX512) set_private_option(ctx, "x264-params", "asm=AVX2");
  } else if (encoder == "libx265") {
    set_private_option(ctx, "preset", "medium");
    set_private_option(ctx, "crf", std::to_string(crf));
    // x265 prints its settings on stderr, which belongs to the progress display; its thread
    // pool would size itself to the machine.
    set_private_option(ctx, "x265-params", "log-level=error:pools=4:frame-threads=2");
  } else if (encoder == "libvpx-vp9" || encoder == "libaom-av1") {
    ctx->bit_rate = 0;  // constant quality: crf alone
    set_private_option(ctx, "crf", std::to_string(crf));
    // Speed over the last percent of compression: the defaults take minutes a second of video.
    set_private_option(ctx, "cpu-used", encoder == "libaom-av1" ? "6" : "4");
    set_private_option(ctx, "row-mt", "1");
  } else if (spec.name == std::string("ffv1")) {
    ctx->level = 3;  // FFV1 version 3: slices, CRCs, multithreaded decoding
  } else if (encoder == "libwebp_anim") {
    // libwebp's quality runs the other way: crf 18 -> 82, crf 0 -> 100.
    av_check(av_opt_set_double(ctx->priv_data, "quality", 100.0 - crf, 0), "setting webp quality");
  } else if (encoder == "prores_ks") {
    set_private_option(ctx, "profile", "4444");
  }
}

}  // namespace sdfreel
