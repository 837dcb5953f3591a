// The frame EXRs' own PIZ coder against OpenEXR itself: its Huffman coding and wavelet against
// OpenEXR's exported hufCompress and wav2Encode, and whole files against Imf::OutputFile, byte for
// byte, for images of every shape and kind of content (flat, smooth, noise that PIZ cannot shrink,
// values wide enough for the 16-bit wavelet, float channels beside half ones).
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHuf.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfWav.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "io/exr_huffman.h"
#include "io/exr_memory_stream.h"
#include "io/exr_piz_file.h"
#include "io/exr_wavelet.h"

namespace sdfreel {
namespace {

std::vector<char> openexr_huffman(const std::vector<uint16_t>& raw) {
  std::vector<char> out(2 * raw.size() + 65536);
  out.resize(size_t(Imf::hufCompress(raw.data(), int(raw.size()), out.data())));
  return out;
}

void expect_huffman_bytes(const std::vector<uint16_t>& raw, const char* what) {
  std::vector<char> ours;
  const size_t written = exr_huffman_compress(raw.data(), raw.size(), ours);
  EXPECT_EQ(written, ours.size()) << what;
  EXPECT_EQ(ours, openexr_huffman(raw)) << what << ", " << raw.size() << " values";
}

TEST(ExrHuffman, OpenExrsStreamForEveryKindOfData) {
  std::mt19937 rng(5);
  auto values = [&](size_t n, uint32_t lo, uint32_t spread) {
    std::vector<uint16_t> v(n);
    for (uint16_t& x : v) x = uint16_t(lo + rng() % spread);
    return v;
  };
  expect_huffman_bytes({}, "nothing");
  expect_huffman_bytes({7}, "one value");
  expect_huffman_bytes(std::vector<uint16_t>(5000, 0), "one value repeated: runs of 256");
  expect_huffman_bytes(std::vector<uint16_t>(300, 0xffff),
                       "the highest value: the run symbol 65536");
  expect_huffman_bytes(values(100000, 0, 65536), "every value: no zero runs in the table");
  expect_huffman_bytes(values(20000, 1000, 40), "a narrow range far from zero");
  // Present values with gaps of every length around the table's run pieces (1, 2-5, 6-261, more).
  std::vector<uint16_t> gaps;
  for (int gap : {1, 2, 3, 5, 6, 7, 260, 261, 262, 263, 600, 9000})
    for (int k = 0; k < 3; ++k) gaps.push_back(uint16_t(gaps.empty() ? 0 : gaps.back() + gap));
  expect_huffman_bytes(gaps, "gaps between present values");
  // Runs around where the run symbol starts to pay, and longer than 255.
  std::vector<uint16_t> runs;
  for (int run = 1; run < 300; run += 7)
    for (int k = 0; k < run; ++k) runs.push_back(uint16_t(run % 13));
  expect_huffman_bytes(runs, "runs of every length");
}

TEST(ExrHuffman, LongCodesAsOpenExrBuildsThem) {
  // Values counted 1, 1, 2, 3, 5, 8... make the deepest tree: codes of 25 bits and more, ties
  // between equal counts settled by value as OpenEXR's heap settles them.
  std::vector<uint16_t> raw;
  uint64_t a = 1, b = 1;
  for (uint16_t v = 0; v < 27; ++v) {
    for (uint64_t k = 0; k < a; ++k) raw.push_back(uint16_t(v * 97 + 3));
    const uint64_t next = a + b;
    a = b;
    b = next;
  }
  std::mt19937 rng(3);
  std::shuffle(raw.begin(), raw.end(), rng);
  expect_huffman_bytes(raw, "Fibonacci counts");
}

TEST(ExrWavelet, OpenExrsTransformAtEveryShape) {
  std::mt19937 rng(9);
  for (int nx : {1, 2, 3, 7, 32, 33, 100})
    for (int ny : {1, 2, 5, 16, 32})
      for (uint16_t max : {uint16_t(300), uint16_t(20000)}) {  // the 14- and the 16-bit one
        const int words = 2;  // two interleaved channels, as a float's halves are
        std::vector<uint16_t> v(size_t(nx * ny * words));
        for (uint16_t& x : v) x = uint16_t(rng() % (uint32_t(max) + 1));
        std::vector<uint16_t> theirs = v;
        for (int w = 0; w < words; ++w) {
          exr_wavelet_encode(v.data() + w, nx, words, ny, nx * words, max);
          Imf::wav2Encode(theirs.data() + w, nx, words, ny, nx * words, max);
        }
        EXPECT_EQ(v, theirs) << nx << "x" << ny << ", max " << max;
      }
}

// An image of `width` x `height`: RGBA halves and `floats` float channels from `value(x, y, c)`.
struct TestImage {
  Imf::Header header;
  std::vector<Imath::half> halves;
  std::vector<float> floats;
  Imf::FrameBuffer frame;
};

template <class Value>
TestImage make_image(int width, int height, int float_channels, Value value) {
  TestImage t{Imf::Header(width, height), {}, {}, {}};
  t.header.compression() = Imf::PIZ_COMPRESSION;
  t.header.insert("sdfreel:note", Imf::StringAttribute("a test"));
  const size_t pixels = size_t(width) * size_t(height);
  t.halves.resize(pixels * 4);
  t.floats.resize(pixels * size_t(float_channels));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t p = size_t(y) * size_t(width) + size_t(x);
      for (int c = 0; c < 4; ++c) t.halves[p * 4 + size_t(c)] = Imath::half(value(x, y, c));
      for (int c = 0; c < float_channels; ++c)
        t.floats[p * size_t(float_channels) + size_t(c)] = value(x, y, 4 + c);
    }
  const char* rgba[4] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c) {
    t.header.channels().insert(rgba[c], Imf::Channel(Imf::HALF));
    t.frame.insert(rgba[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(t.halves.data() + c), 8,
                                       8 * size_t(width)));
  }
  for (int c = 0; c < float_channels; ++c) {
    const std::string name = "pass." + std::to_string(c);
    const size_t step = sizeof(float) * size_t(float_channels);
    t.header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    t.frame.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(t.floats.data() + c), step,
                                    step * size_t(width)));
  }
  return t;
}

std::vector<char> openexr_file(const TestImage& t) {
  ExrMemoryStream stream;
  {
    Imf::OutputFile file(stream, t.header);
    file.setFrameBuffer(t.frame);
    file.writePixels(t.header.dataWindow().max.y - t.header.dataWindow().min.y + 1);
  }
  return stream.take();
}

template <class Value>
void expect_file_bytes(int width, int height, int float_channels, Value value, const char* what) {
  const TestImage t = make_image(width, height, float_channels, value);
  EXPECT_EQ(encode_piz_exr(t.header, t.frame), openexr_file(t))
      << what << ", " << width << "x" << height << ", " << float_channels << " float channels";
}

TEST(ExrPizFile, OpenExrsBytesForEveryShapeAndContent) {
  const auto smooth = [](int x, int y, int c) {
    return 0.25f + 0.5f * std::sin(0.05f * float(x) + 0.3f * float(c)) * std::cos(0.07f * float(y));
  };
  for (int width : {1, 2, 31, 64, 173})
    for (int height : {1, 31, 32, 33, 70}) expect_file_bytes(width, height, 0, smooth, "smooth");
  expect_file_bytes(
      64, 40, 0, [](int, int, int) { return 0.0f; }, "all zero: an empty bitmap");
  expect_file_bytes(
      64, 40, 0, [](int, int, int) { return 0.5f; }, "flat");
  std::mt19937 rng(1);
  expect_file_bytes(
      96, 50, 0,
      [&](int, int, int) { return std::ldexp(float(rng() % 4096), int(rng() % 30) - 15); },
      "noise PIZ cannot shrink: chunks stored raw");
  expect_file_bytes(
      256, 64, 0, [&](int, int, int) { return float(rng() % 60000) - 30000.0f; },
      "more than 1 << 14 values in a chunk: the 16-bit wavelet");
  expect_file_bytes(80, 45, 3, smooth, "float channels beside half ones");
  expect_file_bytes(
      40, 33, 2, [&](int, int, int) { return float(rng()) * 1e-3f; }, "noisy float channels");
}

TEST(ExrPizFile, FloatSlicesOfHalfChannelsAreTheFileOfTheirRoundedHalves) {
  // encode_exr hands the frame's floats to half channels and each chunk rounds its own: the file
  // OpenEXR writes from the halves Imath rounds (OpenEXR takes no float slice for a half channel).
  std::mt19937 rng(4);
  std::vector<float> rgba(size_t(70 * 45 * 4));
  for (float& v : rgba) v = std::ldexp(float(rng() % 100000) / 1e5f, int(rng() % 20) - 10);
  const std::vector<Imath::half> halves(rgba.begin(), rgba.end());
  Imf::Header header(70, 45);
  header.compression() = Imf::PIZ_COMPRESSION;
  Imf::FrameBuffer floats, rounded;
  const char* names[4] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::HALF));
    floats.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rgba.data() + c),
                                       4 * sizeof(float), 4 * sizeof(float) * 70));
    rounded.insert(
        names[c],
        Imf::Slice(Imf::HALF, reinterpret_cast<char*>(const_cast<Imath::half*>(halves.data() + c)),
                   4 * sizeof(Imath::half), 4 * sizeof(Imath::half) * 70));
  }
  ExrMemoryStream stream;
  {
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(rounded);
    file.writePixels(45);
  }
  EXPECT_EQ(encode_piz_exr(header, floats), stream.take());
}

TEST(ExrPizFile, FloatOnlyFilesToo) {
  TestImage t = make_image(50, 40, 4, [](int x, int y, int c) { return float(x * y + c) / 7.0f; });
  // Only the float channels: the compressor's XDR layout instead of the native one.
  Imf::Header floats_only(50, 40);
  floats_only.compression() = Imf::PIZ_COMPRESSION;
  Imf::FrameBuffer frame;
  for (auto c = t.header.channels().begin(); c != t.header.channels().end(); ++c)
    if (c.channel().type == Imf::FLOAT) {
      floats_only.channels().insert(c.name(), c.channel());
      frame.insert(c.name(), t.frame[c.name()]);
    }
  t.header = floats_only;
  t.frame = frame;
  EXPECT_EQ(encode_piz_exr(t.header, t.frame), openexr_file(t));
}

}  // namespace
}  // namespace sdfreel
