#pragma once
// What each codec name of the timeline means in libav: encoder, pixel format, colour tags and
// private options. Kept apart from the encoding loop so the choices can be read in one place.
#include <string>

extern "C" {
#include <libavutil/pixfmt.h>
}

namespace sdfreel {

struct VideoCodecSpec {
  const char* name;       // timeline/video_codec_rules.h's names
  const char* encoder;    // libav encoder name
  AVPixelFormat pix_fmt;  // what the encoder is fed
  bool yuv;               // RGB -> Y'CbCr with the BT.709 matrix, limited (tv) range
  bool even_size;         // chroma halved in both directions: width and height must be even
  int threads;            // a fixed count, never "auto": see video_codecs.cpp
  bool bt601 = false;     // Y'CbCr by the BT.601 matrix (WebP's), not BT.709
};

const VideoCodecSpec* find_video_codec(const std::string& name);  // nullptr when unknown
std::string known_video_codecs();                                 // "h264, ..., prores"
// "" when this machine's libav has the codec's encoder; else what is missing, for the user. A
// known codec's check opens the video module (io/video_module.h), so it is defined beside the
// encoder's face in video_encoder.cpp: this file's table is compiled into the module too.
std::string missing_video_encoder(const std::string& codec);

}  // namespace sdfreel
