#pragma once
// FFmpeg's libavcodec, libavformat, libswscale and libswresample pull in 127 shared libraries
// (x264, x265, libvpx, GnuTLS, ...) whose binding took 31 ms of every start of sdfreel, two frames'
// file writing. A render without a video never needs them: they live in a module of sdfreel's
// own, lib/sdfreel/sdfreel_video_av.so (src/plugins/video_av/), opened with dlopen the first time
// a video or a soundtrack is encoded or its encoder is checked. io/video_encoder.h,
// io/video_codecs.h, io/audio_track.h and the soundtrack's check (cli/soundtrack.cpp) call
// through it; nothing else does.
#include <cstddef>
#include <memory>
#include <string>

namespace sdfreel {

struct AudioCut;
struct EncodedAudio;
struct ImageRGB16;
struct VideoSettings;

// One video being encoded (io/video_encoder.h's VideoEncoder holds one).
class EncoderSession {
 public:
  virtual ~EncoderSession() = default;
  virtual void add_frame(const ImageRGB16& display) = 0;
  virtual void finish() = 0;
};

// What the module takes from sdfreel: the video file's writes go through io/atomic_file.h's
// functions of the process (one count of file operations for the fault-injection tests).
struct VideoHost {
  std::string (*temp_path_for)(const std::string& path);
  int (*write_fully)(int fd, const void* data, size_t size);
  int (*sync_and_close)(int fd);
  void (*commit_temp_file)(const std::string& temp, const std::string& path);
  void (*discard_temp_file)(const std::string& temp) noexcept;
};

// The module's entry points; each throws std::runtime_error as the function it stands for.
struct VideoModule {
  int abi = 0;                                      // VIDEO_MODULE_ABI of the build that made it
  void (*attach)(const VideoHost& host) = nullptr;  // once, before any other
  std::unique_ptr<EncoderSession> (*open_encoder)(const VideoSettings& settings) = nullptr;
  // Whether libav has `encoder` (a libav encoder name).
  bool (*has_encoder)(const std::string& encoder) = nullptr;
  // The cut encoded with `encoder` (aac, libopus or pcm_s16le) for the container of `video_path`.
  std::shared_ptr<const EncodedAudio> (*encode_soundtrack)(const AudioCut& cut,
                                                           const std::string& encoder,
                                                           const std::string& video_path) = nullptr;
  // How many stereo frames, up to `frames`, the audio file starts with (0: none, not audio).
  size_t (*audio_frames)(const std::string& path, size_t frames) = nullptr;
};

// Bumped when VideoModule or the types it passes change: a module of another build is refused.
constexpr int VIDEO_MODULE_ABI = 1;
// The C name the module exports, returning a const VideoModule*.
#define SDFREEL_VIDEO_MODULE_ENTRY "sdfreel_video_module"
#define SDFREEL_VIDEO_MODULE "sdfreel_video_av.so"

// The module, opened on first use and kept for the process. Throws std::runtime_error naming the
// files tried when it is missing or of another build.
const VideoModule& video_module();

}  // namespace sdfreel
