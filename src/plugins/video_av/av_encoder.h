#pragma once
// The video module's encoder: libav's, frames in as they finish, the file published on finish().
#include <memory>

#include "io/video_module.h"

namespace sdfreel {

// Throws std::runtime_error naming what libav refused.
std::unique_ptr<EncoderSession> open_av_encoder(const VideoSettings& s);

}  // namespace sdfreel
