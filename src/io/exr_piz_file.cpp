#include "io/exr_piz_file.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfOutputFile.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "io/exr_memory_stream.h"
#include "io/exr_piz.h"
#include "io/little_endian.h"

namespace sdfreel {

namespace {

constexpr int PIZ_LINES = 32;  // scanlines a PIZ chunk holds

// A channel's values as OpenEXR's line buffers see them: 16-bit words, little-endian (the
// host's order here and the file's).
struct ChannelSource {
  const char* base = nullptr;  // null: zeros
  size_t x_stride = 0, y_stride = 0;
  int words = 1;
  bool float_to_half = false;  // a float slice of a half channel: rounded here by Imath
  void copy_row(int y, int min_x, int nx, uint16_t* to) const {
    if (!base) {
      std::memset(to, 0, size_t(words) * sizeof(uint16_t) * size_t(nx));
      return;
    }
    const char* from =
        base + intptr_t(y) * intptr_t(y_stride) + intptr_t(min_x) * intptr_t(x_stride);
    if (float_to_half) {
      for (int x = 0; x < nx; ++x, from += x_stride) {
        float f;
        std::memcpy(&f, from, sizeof f);
        to[x] = Imath::half(f).bits();
      }
    } else if (words == 1) {  // a constant size, so the copies are loads and stores, not calls
      for (int x = 0; x < nx; ++x, from += x_stride) std::memcpy(to + x, from, 2);
    } else {
      for (int x = 0; x < nx; ++x, from += x_stride) std::memcpy(to + 2 * x, from, 4);
    }
  }
};

std::vector<ChannelSource> channel_sources(const Imf::Header& header,
                                           const Imf::FrameBuffer& frame) {
  std::vector<ChannelSource> sources;
  for (auto c = header.channels().begin(); c != header.channels().end(); ++c) {
    if (c.channel().xSampling != 1 || c.channel().ySampling != 1)
      throw std::logic_error("encode_piz_exr: subsampled channel " + std::string(c.name()));
    ChannelSource s;
    s.words = c.channel().type == Imf::HALF ? 1 : 2;
    if (const Imf::Slice* slice = frame.findSlice(c.name())) {
      s.float_to_half = slice->type == Imf::FLOAT && c.channel().type == Imf::HALF;
      if ((slice->type != c.channel().type && !s.float_to_half) || slice->xSampling != 1 ||
          slice->ySampling != 1)
        throw std::logic_error("encode_piz_exr: slice " + std::string(c.name()) +
                               " differs from its channel");
      s.base = slice->base;
      s.x_stride = slice->xStride;
      s.y_stride = slice->yStride;
    }
    sources.push_back(s);
  }
  return sources;
}

// Lines [y0, y1] as OpenEXR stores a chunk: PIZ, or the lines raw (channel after channel within a
// line) where PIZ is not smaller.
std::vector<char> code_chunk(const std::vector<ChannelSource>& sources, int min_x, int nx, int y0,
                             int y1) {
  const int ny = y1 - y0 + 1;
  size_t words = 0;
  std::vector<PizChannel> channels;
  for (const ChannelSource& s : sources) {
    channels.push_back({nx, ny, s.words});
    words += size_t(nx) * size_t(ny) * size_t(s.words);
  }
  std::vector<uint16_t> values(words);
  uint16_t* to = values.data();
  for (const ChannelSource& s : sources)
    for (int y = y0; y <= y1; ++y, to += size_t(nx) * size_t(s.words)) s.copy_row(y, min_x, nx, to);
  std::vector<char> coded = piz_compress(values, channels);
  if (coded.size() < words * sizeof(uint16_t)) return coded;
  std::vector<uint16_t> lines(words);
  to = lines.data();
  for (int y = y0; y <= y1; ++y)
    for (const ChannelSource& s : sources) {
      s.copy_row(y, min_x, nx, to);
      to += size_t(nx) * size_t(s.words);
    }
  const char* raw = reinterpret_cast<const char*>(lines.data());
  return std::vector<char>(raw, raw + words * sizeof(uint16_t));
}

}  // namespace

std::vector<char> encode_piz_exr(const Imf::Header& header, const Imf::FrameBuffer& frame) {
  if (header.compression() != Imf::PIZ_COMPRESSION || header.lineOrder() != Imf::INCREASING_Y)
    throw std::logic_error("encode_piz_exr: not a PIZ file of increasing y");
  ExrMemoryStream stream;
  { Imf::OutputFile prefix(stream, header); }  // its destructor writes the (empty) offset table
  std::vector<char> file = stream.take();
  const Imath::Box2i& dw = header.dataWindow();
  const int nx = dw.max.x - dw.min.x + 1, height = dw.max.y - dw.min.y + 1;
  const int chunks = (height + PIZ_LINES - 1) / PIZ_LINES;
  const size_t table = file.size() - size_t(chunks) * sizeof(uint64_t);
  const std::vector<ChannelSource> sources = channel_sources(header, frame);
  std::vector<std::vector<char>> coded(static_cast<size_t>(chunks));
  tbb::parallel_for(0, chunks, [&](int k) {
    const int y0 = dw.min.y + k * PIZ_LINES;
    coded[size_t(k)] =
        code_chunk(sources, dw.min.x, nx, y0, std::min(y0 + PIZ_LINES - 1, dw.max.y));
  });
  size_t total = file.size();
  for (const std::vector<char>& c : coded) total += 8 + c.size();
  file.reserve(total);
  for (int k = 0; k < chunks; ++k) {
    const uint64_t at = file.size();
    store_le(&file[table + size_t(k) * 8], at, 8);
    append_le(file, uint32_t(dw.min.y + k * PIZ_LINES), 4);
    append_le(file, coded[size_t(k)].size(), 4);
    file.insert(file.end(), coded[size_t(k)].begin(), coded[size_t(k)].end());
  }
  return file;
}

}  // namespace sdfreel
