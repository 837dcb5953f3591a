// The video module's one exported name (io/video_module.h): its entry points, for sdfreel's dlopen.
#include "io/video_module.h"
#include "plugins/video_av/audio_source.h"
#include "plugins/video_av/av_encoder.h"
#include "plugins/video_av/av_soundtrack.h"
#include "plugins/video_av/module/host.h"

namespace sdfreel {
namespace {

bool has_encoder(const std::string& encoder) {
  return avcodec_find_encoder_by_name(encoder.c_str()) != nullptr;
}

size_t audio_frames(const std::string& path, size_t frames) {
  AudioSource source(path, 0.0);
  std::vector<float> samples;
  return source.read(samples, frames);
}

}  // namespace
}  // namespace sdfreel

extern "C" __attribute__((visibility("default"))) const sdfreel::VideoModule*
sdfreel_video_module() {
  static const sdfreel::VideoModule module{sdfreel::VIDEO_MODULE_ABI,      &sdfreel::attach_host,
                                           &sdfreel::open_av_encoder,      &sdfreel::has_encoder,
                                           &sdfreel::encode_av_soundtrack, &sdfreel::audio_frames};
  return &module;
}
