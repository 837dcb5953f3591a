// The soundtrack under a video: the codec each container takes, the cut (offset into the file,
// the video's length, silence past the file's end), the fade-out, and sync (both streams start
// at 0 and last as long), read back with stock ffprobe and ffmpeg.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>

#include "io/audio_track.h"
#include "io/video_decode.h"
#include "io/video_test_support.h"
#include "support/wav_file.h"

namespace sdfreel::test {
namespace {

using SoundtrackTest = VideoTest;

// 10 frames at 10 fps (1 s of video) with `cut`'s audio.
void encode_with_audio(const std::string& path, const std::string& codec, AudioCut cut) {
  std::vector<ImageRGB16> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(gradient_frame(64, 36, i));
  cut.length = 1.0;
  VideoSettings s;
  s.path = path;
  s.codec = codec;
  s.width = 64;
  s.height = 36;
  s.fps = {10, 1};
  s.audio = encode_soundtrack(cut, path);
  VideoEncoder enc(s);
  for (const ImageRGB16& f : frames) enc.add_frame(f);
  enc.finish();
}

struct Stream {
  std::string type, codec;
  double start = 0, duration = 0;
};

std::vector<Stream> streams(const std::string& path) {
  int status = 0;
  const std::string out = run_command(
      "ffprobe -v error -show_entries stream=codec_type,codec_name,start_time,duration -of "
      "csv=p=0 '" +
          path + "'",
      &status);
  std::vector<Stream> result;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream fields(line);
    Stream s;
    std::string start, duration;
    std::getline(fields, s.codec, ',');
    std::getline(fields, s.type, ',');
    std::getline(fields, start, ',');
    std::getline(fields, duration, ',');
    s.start = std::atof(start.c_str());
    s.duration = std::atof(duration.c_str());
    result.push_back(s);
  }
  return result;
}

// The file's audio as 48 kHz mono 16-bit samples, decoded by stock ffmpeg.
std::vector<int16_t> decoded_audio(const std::string& path) {
  int status = 0;
  const std::string raw =
      run_command("ffmpeg -v error -i '" + path + "' -vn -ac 1 -ar 48000 -f s16le -", &status);
  std::vector<int16_t> samples(raw.size() / 2);
  std::memcpy(samples.data(), raw.data(), samples.size() * 2);
  return samples;
}

double rms(const std::vector<int16_t>& s, double from, double to) {
  double sum = 0;
  size_t n = 0;
  for (size_t i = size_t(from * 48000); i < size_t(to * 48000) && i < s.size(); ++i, ++n)
    sum += double(s[i]) * s[i];
  return n ? std::sqrt(sum / n) / 32767.0 : 0.0;
}

TEST_F(SoundtrackTest, EachContainerTakesItsCodecAndBothStreamsStartAtZeroAndLastAsLong) {
  if (!have_program("ffprobe")) GTEST_SKIP() << "ffprobe not installed";
  write_tone_wav(file("tone.wav"), 3.0, 44100, 0.0);  // resampled to 48 kHz
  const struct {
    const char* file;
    const char* codec;
    const char* audio;
  } cases[] = {{"a.mp4", "h264", "aac"},
               {"b.webm", "vp9", "opus"},
               {"c.mkv", "ffv1", "opus"},
               {"d.mov", "prores", "pcm_s16le"}};
  for (const auto& c : cases) {
    encode_with_audio(file(c.file), c.codec, {file("tone.wav"), 0.5, 0.0, 0.0});
    const std::vector<Stream> s = streams(file(c.file));
    ASSERT_EQ(s.size(), 2u) << c.file;
    EXPECT_EQ(s[0].type, "video");
    EXPECT_EQ(s[1].type, "audio");
    EXPECT_EQ(s[1].codec, c.audio) << c.file;
    // MP4 and MOV: the video at 0. WebM and MKV: Matroska's Opus codec delay (6.5 ms, in
    // milliseconds) moves the video to 0.007 and the audio to -0.007, as stock ffmpeg does.
    EXPECT_NEAR(s[0].start, 0.0, 0.0071) << c.file;
    // AAC's and Opus's priming is in the edit list or the pre-skip, which players drop.
    EXPECT_NEAR(s[1].start, 0.0, 0.025) << c.file;
    if (s[1].duration > 0) {  // WebM and MKV give the stream no duration of its own
      EXPECT_NEAR(s[1].duration, 1.0, 0.03) << c.file;
    }
    const std::vector<int16_t> audio = decoded_audio(file(c.file));
    EXPECT_NEAR(audio.size() / 48000.0, 1.0, 0.03) << c.file;
    EXPECT_NEAR(rms(audio, 0.1, 0.9), 0.5 / std::sqrt(2.0), 0.03) << c.file;
  }
}

TEST_F(SoundtrackTest, TheOffsetCutsTheFileAndSilenceFollowsItsEnd) {
  // 0.5 s of silence, then the tone, for 1.3 s in all.
  write_tone_wav(file("late.wav"), 1.3, 48000, 0.5);
  encode_with_audio(file("at0.mov"), "prores", {file("late.wav"), 0.0, 0.0, 0.0});
  encode_with_audio(file("at05.mov"), "prores", {file("late.wav"), 0.5, 0.0, 0.0});
  const std::vector<int16_t> at0 = decoded_audio(file("at0.mov"));
  const std::vector<int16_t> at05 = decoded_audio(file("at05.mov"));
  EXPECT_LT(rms(at0, 0.0, 0.49), 0.001);  // the file's silence
  EXPECT_GT(rms(at0, 0.51, 0.99), 0.3);   // then its tone
  EXPECT_GT(rms(at05, 0.0, 0.1), 0.3);    // cut at 0.5 s: the tone from the first sample
  EXPECT_GT(rms(at05, 0.7, 0.79), 0.3);
  EXPECT_LT(rms(at05, 0.81, 1.0), 0.001);  // the file ended at 0.8 s of video: silence
  EXPECT_NEAR(at05.size() / 48000.0, 1.0, 0.001);
}

TEST_F(SoundtrackTest, TheFadeEndsInSilence) {
  write_tone_wav(file("tone.wav"), 2.0, 48000, 0.0);
  encode_with_audio(file("f.mov"), "prores", {file("tone.wav"), 0.0, 0.0, 0.5});
  const std::vector<int16_t> a = decoded_audio(file("f.mov"));
  const double full = rms(a, 0.1, 0.45), middle = rms(a, 0.7, 0.8), end = rms(a, 0.97, 1.0);
  EXPECT_NEAR(full, 0.5 / std::sqrt(2.0), 0.01);
  EXPECT_NEAR(middle / full, 0.5, 0.1);  // linear: half way down at 0.75 s
  EXPECT_LT(end / full, 0.1);
}

TEST_F(SoundtrackTest, AFileThatIsNotAudioIsNamed) {
  std::ofstream(file("not.wav")) << "this is text";
  try {
    encode_soundtrack({file("not.wav"), 0.0, 1.0, 0.0}, file("v.mp4"));
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not.wav"), std::string::npos) << e.what();
  }
  EXPECT_THROW(encode_soundtrack({file("missing.flac"), 0.0, 1.0, 0.0}, file("v.mp4")),
               std::runtime_error);
}

}  // namespace
}  // namespace sdfreel::test
