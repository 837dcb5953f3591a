// The video encoder's face in sdfreel, and the check of a codec's encoder: their work is the
// video module's (io/video_module.h).
#include "io/video_encoder.h"

#include "io/video_codecs.h"
#include "io/video_module.h"

namespace sdfreel {

VideoEncoder::VideoEncoder(const VideoSettings& s) : session_(video_module().open_encoder(s)) {}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::add_frame(const ImageRGB16& display) {
  session_->add_frame(display);
}

void VideoEncoder::finish() {
  session_->finish();
}

std::string missing_video_encoder(const std::string& codec) {
  const VideoCodecSpec* spec = find_video_codec(codec);
  if (!spec) return "unknown codec '" + codec + "' (known: " + known_video_codecs() + ")";
  if (video_module().has_encoder(spec->encoder)) return "";
  return "codec " + codec + " needs libav's " + spec->encoder +
         " encoder, which this machine's libav lacks (`ffmpeg -encoders` lists what it has)";
}

bool is_known_codec(const std::string& codec) {
  return find_video_codec(codec) != nullptr;
}

}  // namespace sdfreel
