#include "cli/soundtrack.h"

#include <cstdio>
#include <stdexcept>

#include "io/bounded_read.h"
#include "io/video_module.h"
#include "pipeline/errors.h"
#include "timeline/sha256.h"

namespace sdfreel {
namespace {

constexpr uint64_t kMaxAudioBytes = uint64_t(1) << 30;

std::string file_sha256(const std::string& path) {
  const std::optional<std::string> bytes = read_regular_file(path, kMaxAudioBytes);
  if (!bytes) throw std::runtime_error(path + ": no such file");
  return sha256_hex(*bytes);
}

}  // namespace

void check_soundtrack(const Timeline& tl) {
  if (tl.audio.path.empty()) return;
  try {
    // A FIFO would block the decoder's open; the bytes are read once, for the manifest's hash.
    check_regular_file(tl.audio.path, kMaxAudioBytes);
    if (video_module().audio_frames(tl.audio.path, 1024) == 0)
      throw std::runtime_error(tl.audio.path + ": it holds no audio samples");
  } catch (const std::exception& e) {
    throw InputError(tl.path, tl.audio.line, tl.audio.column,
                     std::string("output.audio: ") + e.what());
  }
}

std::string soundtrack_sha256(const Timeline& tl) {
  if (tl.audio.path.empty()) return "";
  try {
    return file_sha256(tl.audio.path);
  } catch (const std::exception&) {
    return "";  // verify needs no audio; render checked it first (check_soundtrack)
  }
}

std::shared_ptr<const EncodedAudio> render_soundtrack(const Timeline& tl,
                                                      const std::vector<int>& frames,
                                                      const std::string& video_path,
                                                      bool makes_video) {
  if (tl.audio.path.empty() || !makes_video || frames.empty()) return nullptr;
  const double fps = tl.fps.value();
  const AudioCut cut{tl.audio.path, tl.audio.offset + frames.front() / fps,
                     double(frames.size()) / fps, tl.audio.fade};
  try {
    return encode_soundtrack(cut, video_path);
  } catch (const std::exception& e) {
    throw InputError(tl.path, tl.audio.line, tl.audio.column,
                     std::string("output.audio: ") + e.what());
  }
}

std::shared_ptr<const EncodedAudio> encode_soundtrack_of(const ManifestHeader& h, Rational fps,
                                                         const std::string& video_path) {
  if (h.audio_path.empty()) return nullptr;
  if (soundtrack_encoder_for(video_path).empty()) {
    std::fprintf(stderr, "note: %s holds no sound: the render's soundtrack is left out\n",
                 video_path.c_str());
    return nullptr;
  }
  std::string now;
  try {
    now = file_sha256(h.audio_path);
  } catch (const std::exception& e) {
    throw UsageError("the render's soundtrack is gone: " + std::string(e.what()));
  }
  if (now != h.audio_sha256)
    throw UsageError("the render's soundtrack " + h.audio_path +
                     " changed since the render (its SHA-256 differs): render again, or "
                     "restore the file");
  const AudioCut cut{h.audio_path, h.audio_offset,
                     double(h.frame_count) * double(fps.den) / double(fps.num), h.audio_fade};
  return encode_soundtrack(cut, video_path);
}

}  // namespace sdfreel
