#pragma once
// A 16-bit PCM WAV file written by hand, for the soundtrack tests: a tone that starts after a
// silence, so a test can tell where the cut began.
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace sdfreel::test {

// `seconds` of stereo at `rate`: silence for `silent_seconds`, then a sine of `hz` at `amplitude`
// (0..1) in both channels.
inline void write_tone_wav(const std::string& path, double seconds, int rate, double silent_seconds,
                           double hz = 440.0, double amplitude = 0.5) {
  const uint32_t frames = uint32_t(std::lround(seconds * rate));
  std::vector<int16_t> samples(size_t(frames) * 2);
  for (uint32_t i = 0; i < frames; ++i) {
    const double t = double(i) / rate;
    const double v = t < silent_seconds ? 0.0 : amplitude * std::sin(2.0 * M_PI * hz * t);
    samples[2 * i] = samples[2 * i + 1] = int16_t(std::lround(v * 32767.0));
  }
  const uint32_t data = uint32_t(samples.size() * 2);
  std::ofstream out(path, std::ios::binary);
  auto u32 = [&](uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };
  auto u16 = [&](uint16_t v) { out.write(reinterpret_cast<const char*>(&v), 2); };
  out.write("RIFF", 4);
  u32(36 + data);
  out.write("WAVEfmt ", 8);
  u32(16);
  u16(1);  // PCM
  u16(2);
  u32(uint32_t(rate));
  u32(uint32_t(rate) * 4);
  u16(4);
  u16(16);
  out.write("data", 4);
  u32(data);
  out.write(reinterpret_cast<const char*>(samples.data()), data);
}

}  // namespace sdfreel::test
