#pragma once
// The codec a video file name asks for, shared by `encode -o` and `render --video`: the container
// names it (.mp4 h264, .mkv ffv1, .mov prores); where the render's own codec fits the container as
// well and is another one (h264 in a .mkv), the name is ambiguous and refused.
#include <string>

namespace sdfreel {

// Throws UsageError naming `option` for an ambiguous name.
std::string codec_of_output(const std::string& name, const std::string& render_codec,
                            const std::string& option);

}  // namespace sdfreel
