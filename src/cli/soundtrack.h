#pragma once
// The soundtrack of a render ([output] audio) and of `encode` (the one its manifest names):
// checked before any frame is rendered, encoded for the video's container (io/audio_track.h).
#include <memory>
#include <string>
#include <vector>

#include "io/audio_track.h"
#include "io/manifest.h"
#include "timeline/timeline.h"

namespace sdfreel {

// Throws InputError at [output] audio's place when its file is missing, holds no audio libav
// decodes, or is larger than 1 GiB. Nothing when the timeline has none.
void check_soundtrack(const Timeline& tl);
// SHA-256 of the audio file's bytes, for the manifest ("" when the timeline has none, or when
// the file cannot be read: only render, which checks it first, needs the hash).
std::string soundtrack_sha256(const Timeline& tl);

// The soundtrack under a render's video of `frames` (the first at frames[0] / fps), or nullptr
// when there is no video or no audio.
std::shared_ptr<const EncodedAudio> render_soundtrack(const Timeline& tl,
                                                      const std::vector<int>& frames,
                                                      const std::string& video_path,
                                                      bool makes_video);
// The soundtrack the render in a folder named, under its whole video at `fps`. Throws
// UsageError when the file is gone or its bytes changed since the render.
std::shared_ptr<const EncodedAudio> encode_soundtrack_of(const ManifestHeader& h, Rational fps,
                                                         const std::string& video_path);

}  // namespace sdfreel
