#pragma once
// Range rules that both the parser and validate_overrides (command-line overrides) apply. Each
// returns "" when the value is fine, otherwise the error message.
#include <cstdint>
#include <string>

namespace sdfreel {

constexpr int kMaxImageSize = 16384;
constexpr int kMaxSamples = 1024;

std::string check_resolution(int64_t width, int64_t height);
std::string check_samples(int64_t samples);
// yuv420p (h264) halves the chroma planes: width and height must be even.
std::string check_codec_size(const std::string& codec, int64_t width, int64_t height);
// output.video: a plain file name whose container (.mp4, .mkv or .mov) can hold `codec`.
std::string check_video_name(const std::string& name, const std::string& codec);
// The codec a video file's container stands for when none is named: .mp4 h264, .mkv ffv1, .mov
// prores (sdfreel's pairings); "" for any other extension.
std::string usual_codec(const std::string& name);
// The extension of a path's file name in lower case, with its dot (".mp4"); "" for none or a
// hidden file's name (".mp4" alone).
std::string lower_extension(const std::string& path);
// Whether that container can hold `codec` (check_video_name's table).
bool container_holds(const std::string& name, const std::string& codec);
// A path or name from the timeline: no NUL or other control characters (the file system would cut
// the name at a NUL and write somewhere else).
std::string check_path_text(const std::string& key, const std::string& text);

}  // namespace sdfreel
