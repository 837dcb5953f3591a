#include "io/audio_track.h"

#include <stdexcept>

#include "io/video_module.h"
#include "timeline/rules.h"

namespace sdfreel {

std::string soundtrack_encoder_for(const std::string& video_path) {
  const std::string ext = lower_extension(video_path);
  if (ext == ".mp4") return "aac";
  if (ext == ".mov") return "pcm_s16le";
  if (ext == ".webm" || ext == ".mkv") return "libopus";
  return "";  // .webp, .gif: no sound
}

std::shared_ptr<const EncodedAudio> encode_soundtrack(const AudioCut& cut,
                                                      const std::string& video_path) {
  const std::string encoder = soundtrack_encoder_for(video_path);
  if (encoder.empty())
    throw std::runtime_error("a " + lower_extension(video_path) +
                             " video holds no sound: use .mp4, .webm, .mkv or .mov");
  return video_module().encode_soundtrack(cut, encoder, video_path);
}

}  // namespace sdfreel
