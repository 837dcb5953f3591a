#pragma once
// An audio file of any format libav decodes, read as interleaved float stereo at 48 kHz from a
// start time on: what the soundtrack encoder takes (io/audio_track.h).
#include <memory>
#include <string>
#include <vector>

namespace sdfreel {

constexpr int kSoundtrackRate = 48000;  // Opus's own rate; AAC and PCM take it too

class AudioSource {
 public:
  // Opens `path` and skips `start_seconds` of it, decoding (exact, unlike a seek). Throws
  // std::runtime_error naming what is wrong: no such file, no audio stream, no decoder.
  AudioSource(const std::string& path, double start_seconds);
  ~AudioSource();
  // Appends up to `max_frames` stereo frames (2 floats each) to `out`; fewer only at the end of
  // the file. Returns how many it appended.
  size_t read(std::vector<float>& out, size_t max_frames);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sdfreel
