#pragma once
// In-process video encoding with libav (in the video module, io/video_module.h). Frames stream in
// as they finish; memory stays flat.
#include <memory>
#include <string>

#include "render/image.h"
#include "timeline/timeline.h"

namespace sdfreel {

struct EncodedAudio;   // io/audio_track.h
class EncoderSession;  // io/video_module.h

struct VideoSettings {
  std::string path;   // .mp4, .mkv, .mov, .webm; the container follows the path
  std::string codec;  // timeline/video_codec_rules.h's names
  int width = 0, height = 0;
  Rational fps;
  int crf = 18;                               // the lossy codecs
  std::shared_ptr<const EncodedAudio> audio;  // a soundtrack to interleave, or none
};

class VideoEncoder {
 public:
  // Opens the output (written to a temporary name, renamed on finish()). Throws std::runtime_error.
  explicit VideoEncoder(const VideoSettings& s);
  ~VideoEncoder();  // without finish(): removes the temporary file
  void add_frame(const ImageRGB16& display);
  void finish();

 private:
  std::unique_ptr<EncoderSession> session_;
};

bool is_known_codec(const std::string& codec);

}  // namespace sdfreel
