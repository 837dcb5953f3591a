#pragma once
// Reads an FFmpeg framemd5 file (as sdfreel writes it, or as `ffmpeg -f framemd5` prints it):
// header lines start with '#', data lines are "stream, dts, pts, duration, size, hash".
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

namespace sdfreel {

struct Framemd5Frame {
  int64_t size = 0;  // bytes of the hashed frame (6 * width * height for rgb48le)
  std::string md5;   // 32 lowercase hex digits
};

struct Framemd5 {
  std::string hash = "MD5";                 // "#hash:" header; only MD5 is compared
  std::map<int64_t, Framemd5Frame> frames;  // by pts of stream 0
};

// Thrown with "line N: what is wrong" when the text is not a framemd5.
struct Framemd5Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

Framemd5 parse_framemd5(const std::string& text);

}  // namespace sdfreel
