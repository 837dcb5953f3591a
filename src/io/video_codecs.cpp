#include "io/video_codecs.h"

#include <stdexcept>

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

}  // namespace

const VideoCodecSpec* find_video_codec(const std::string& name) {
  for (const VideoCodecSpec& c : kCodecs)
    if (name == c.name) return &c;
  return nullptr;
}

std::string known_video_codecs() {
  std::string out;
  for (const VideoCodecSpec& c : kCodecs) out += (out.empty() ? "" : ", ") + std::string(c.name);
  return out;
}

}  // namespace sdfreel
