#include "io/video_codecs.h"

#include <stdexcept>

extern "C" {
#include <libavutil/cpu.h>
#include <libavutil/opt.h>
}

namespace sdfreel {
namespace {

// Threads: a fixed count, never "auto", so the bytes do not depend on the machine's cores. x264's
// frame threads and FFV1/ProRes slices are deterministic for a given count.
// x265, libvpx and libaom give the same bytes for a given thread count as well.
const VideoCodecSpec kCodecs[] = {
    {"h264", "libx264", AV_PIX_FMT_YUV420P, true, true, 4},
    {"h264-10bit", "libx264", AV_PIX_FMT_YUV420P10LE, true, true, 4},
    {"hevc", "libx265", AV_PIX_FMT_YUV420P, true, true, 4},
    {"hevc-10bit", "libx265", AV_PIX_FMT_YUV420P10LE, true, true, 4},
    {"vp9", "libvpx-vp9", AV_PIX_FMT_YUV420P, true, true, 4},
    {"av1", "libaom-av1", AV_PIX_FMT_YUV420P, true, true, 4},
    // FFV1 keeps rgb48 losslessly as planar gbrp16le.
    {"ffv1", "ffv1", AV_PIX_FMT_GBRP16LE, false, false, 4},
    {"prores", "prores_ks", AV_PIX_FMT_YUV444P10LE, true, false, 4},
    // WebP's lossy frames are VP8's Y'CbCr: BT.601, tv range, what its decoders assume. One
    // thread: libwebp_anim has no others.
    {"webp", "libwebp_anim", AV_PIX_FMT_YUV420P, true, true, 1, true},
    // Paletted by io/palette.h, not swscale (which makes no palette of the frame's own).
    {"gif", "gif", AV_PIX_FMT_PAL8, false, false, 1},
};

void set_private_option(AVCodecContext* ctx, const char* key, const std::string& value) {
  av_check(av_opt_set(ctx->priv_data, key, value.c_str(), 0),
           std::string("setting ") + ctx->codec->name + " option " + key + "=" + value);
}

}  // namespace

const VideoCodecSpec* find_video_codec(const std::string& name) {
  for (const VideoCodecSpec& c : kCodecs)
    if (name == c.name) return &c;
  return nullptr;
}

std::string missing_video_encoder(const std::string& codec) {
  const VideoCodecSpec* spec = find_video_codec(codec);
  if (!spec) return "unknown codec '" + codec + "' (known: " + known_video_codecs() + ")";
  if (avcodec_find_encoder_by_name(spec->encoder)) return "";
  return "codec " + codec + " needs libav's " + spec->encoder +
         " encoder, which this machine's libav lacks (`ffmpeg -encoders` lists what it has)";
}

std::string known_video_codecs() {
  std::string out;
  for (const VideoCodecSpec& c : kCodecs) out += (out.empty() ? "" : ", ") + std::string(c.name);
  return out;
}

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
