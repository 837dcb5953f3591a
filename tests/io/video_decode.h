#pragma once
// Test-only helpers for the video tests: a plain libav decoder, colour conversions written out by
// hand (so they do not share swscale with the encoder under test), and running ffmpeg/ffprobe.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "plugins/video_av/video_av.h"

namespace sdfreel::test {

struct DecodedVideo {
  std::string codec;               // decoder name, e.g. "h264"
  std::vector<AvFramePtr> frames;  // in presentation order
};

// Every frame of the first video stream. Throws std::runtime_error on any libav failure.
DecodedVideo decode_video(const std::string& path);

// Packed rgb48 (r, g, b per pixel) from a gbrp16le frame, by plain copying.
std::vector<uint16_t> gbrp16_to_rgb48(const AVFrame& f);

// Full-range RGB in 0..1 from one pixel of a limited-range BT.709 Y'CbCr frame (yuv420p or
// yuv420p10le, yuv444p10le/12le), using the BT.709 matrix (Kr = 0.2126, Kb = 0.0722).
std::array<double, 3> bt709_pixel_to_rgb(const AVFrame& f, int x, int y);

// Runs a shell command; returns its stdout and sets *status to its exit status.
std::string run_command(const std::string& command, int* status);
bool have_program(const std::string& name);

// `ffprobe -show_streams` of the first video stream, with frames counted, as key -> value.
std::map<std::string, std::string> probe_video_stream(const std::string& path);

// The hash column of `ffmpeg ... -pix_fmt rgb48le -fflags +bitexact -f framemd5 -` data lines.
std::vector<std::string> framemd5_rgb48le(const std::string& path);

}  // namespace sdfreel::test
