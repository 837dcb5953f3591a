#include "timeline/video_codec_rules.h"

namespace sdfreel {

const std::vector<VideoCodecRule>& video_codec_rules() {
  static const std::vector<VideoCodecRule> rules = {
      {"h264", "H.264 (libx264), 8-bit 4:2:0", "yuv420p", true, true},
      {"h264-10bit", "H.264 (libx264), 10-bit 4:2:0", "yuv420p10le", true, true},
      {"hevc", "HEVC (libx265), 8-bit 4:2:0", "yuv420p", true, true},
      {"hevc-10bit", "HEVC (libx265), 10-bit 4:2:0", "yuv420p10le", true, true},
      {"vp9", "VP9 (libvpx), 8-bit 4:2:0", "yuv420p", true, true},
      {"av1", "AV1 (libaom), 8-bit 4:2:0", "yuv420p", true, true},
      {"ffv1", "FFV1, lossless 16-bit RGB", "gbrp16le", false, false},
      {"prores", "ProRes 4444 (prores_ks), 10-bit 4:4:4", "yuv444p10le", false, false},
      {"webp", "animated WebP (libwebp), lossy 4:2:0 BT.601, looping", "yuv420p", true, true},
      {"gif", "GIF, 256 colours a frame (median cut), looping", "pal8", false, false},
  };
  return rules;
}

const VideoCodecRule* find_video_codec_rule(const std::string& name) {
  for (const VideoCodecRule& r : video_codec_rules())
    if (name == r.name) return &r;
  return nullptr;
}

std::vector<std::string> video_codec_names() {
  std::vector<std::string> names;
  for (const VideoCodecRule& r : video_codec_rules()) names.push_back(r.name);
  return names;
}

}  // namespace sdfreel
