#pragma once
// The video module's soundtrack encoder (io/audio_track.h says what a soundtrack is).
#include <memory>
#include <string>

#include "io/audio_track.h"
#include "plugins/video_av/encoded_audio.h"

namespace sdfreel {

// The cut decoded, faded and encoded with `encoder` (soundtrack_encoder_for of the video's path,
// not empty) for the container of `video_path`. Throws std::runtime_error.
std::shared_ptr<const EncodedAudio> encode_av_soundtrack(const AudioCut& cut,
                                                         const std::string& encoder,
                                                         const std::string& video_path);

}  // namespace sdfreel
