#pragma once
// The soundtrack under a video ([output] audio): a stretch of an audio file, cut to the video's
// length (silence after the file's end), faded out if asked, encoded with the codec the video's
// container expects, as packets the video encoder interleaves (io/video_encoder.h).
#include <memory>
#include <string>

namespace sdfreel {

struct AudioCut {
  std::string path;
  double offset = 0.0;  // seconds into the file where the video starts
  double length = 0.0;  // seconds: the video's
  double fade = 0.0;    // seconds of linear fade-out before the end (0: none)
};

// The encoded soundtrack: libav's packets, made and read only in the video module
// (plugins/video_av/encoded_audio.h).
struct EncodedAudio;

// The audio encoder a video file's container takes: AAC in MP4, PCM in MOV, Opus in WebM and
// MKV; "" for an animated WebP or GIF, which hold no sound.
std::string soundtrack_encoder_for(const std::string& video_path);

// Decodes, cuts, fades and encodes (in the video module, io/video_module.h). Throws
// std::runtime_error naming the file and what is wrong.
std::shared_ptr<const EncodedAudio> encode_soundtrack(const AudioCut& cut,
                                                      const std::string& video_path);

}  // namespace sdfreel
