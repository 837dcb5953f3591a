#pragma once
// A codec of io/video_codecs.h's table set up on libav's encoder context.
#include "io/video_codecs.h"
#include "plugins/video_av/video_av.h"

namespace sdfreel {

// Sets size, rates, pixel format, colour tags and the codec's own options before avcodec_open2.
void configure_video_codec(const VideoCodecSpec& spec, AVCodecContext* ctx, int width, int height,
                           AVRational fps, int crf);

}  // namespace sdfreel
