#pragma once
// Video codecs by the names [output] codec and --codec take, with the facts the timeline's rules
// need: whether the picture must have even sides, whether crf sets the quality. What each means
// in libav (encoder, pixel format, options) is io/video_codecs.cpp.
#include <string>
#include <vector>

namespace sdfreel {

struct VideoCodecRule {
  const char* name;
  const char* carries;  // what the video holds, for messages and docs
  const char* pix_fmt;  // libav's name of the pixel format it stores
  bool even_size;       // 4:2:0 chroma, halved both ways: width and height must be even
  bool takes_crf;       // lossy, quality by [output] crf (lower is better)
};

const std::vector<VideoCodecRule>& video_codec_rules();
const VideoCodecRule* find_video_codec_rule(const std::string& name);  // nullptr when unknown
std::vector<std::string> video_codec_names();

}  // namespace sdfreel
