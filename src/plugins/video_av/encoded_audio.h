#pragma once
// The soundtrack as the video encoder muxes it (io/audio_track.h): libav's packets, made and read
// only in the video module.
#include <string>
#include <vector>

#include "plugins/video_av/video_av.h"

namespace sdfreel {

struct EncodedAudio {
  std::string encoder;  // aac, libopus or pcm_s16le
  AVCodecParameters* params = nullptr;
  AVRational time_base{1, 48000};
  std::vector<AvPacketPtr> packets;  // in order, pts in time_base from 0
  EncodedAudio() = default;
  EncodedAudio(const EncodedAudio&) = delete;
  EncodedAudio& operator=(const EncodedAudio&) = delete;
  ~EncodedAudio() { avcodec_parameters_free(&params); }
};

}  // namespace sdfreel
