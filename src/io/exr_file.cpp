#include "io/exr_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#include "io/exr_memory_stream.h"
#include "io/exr_piz_file.h"

namespace sdfreel {

namespace {

constexpr const char* kChannels[4] = {"R", "G", "B", "A"};

struct NamedCompression {
  const char* name;
  Imf::Compression compression;
  bool lossless;
};

constexpr NamedCompression kCompressions[] = {
    {"none", Imf::NO_COMPRESSION, true},    {"rle", Imf::RLE_COMPRESSION, true},
    {"zips", Imf::ZIPS_COMPRESSION, true},  {"zip", Imf::ZIP_COMPRESSION, true},
    {"piz", Imf::PIZ_COMPRESSION, true},    {"dwaa", Imf::DWAA_COMPRESSION, false},
    {"dwab", Imf::DWAB_COMPRESSION, false},
};

const NamedCompression& named_compression(const std::string& name) {
  for (const NamedCompression& c : kCompressions)
    if (name == c.name) return c;
  throw std::runtime_error("unknown EXR compression '" + name + "'");
}

}  // namespace

bool exr_compression_is_lossless(const std::string& compression) {
  return named_compression(compression).lossless;
}

std::vector<char> encode_exr(const ImageRGBA& linear,
                             const std::map<std::string, std::string>& metadata,
                             const ExrSettings& settings, const std::vector<PassImage>& passes) {
  Imf::Header header(linear.width, linear.height);
  // PIZ by default: lossless; faster and smaller than zip on our frames.
  header.compression() = named_compression(settings.compression).compression;
  Imf::addChromaticities(header, Imf::Chromaticities());  // Rec.709 primaries, D65
  for (const auto& [key, value] : metadata)
    header.insert("sdfreel:" + key, Imf::StringAttribute(value));
  // Half channels round the floats (Imath, nearest even): sdfreel's PIZ coder as it gathers each
  // chunk, on all threads; for OpenEXR's coders, here.
  const bool piz = header.compression() == Imf::PIZ_COMPRESSION;
  std::vector<Imath::half> halves;
  if (!settings.full_float && !piz) halves.assign(linear.pixels.begin(), linear.pixels.end());
  const Imf::PixelType type = settings.full_float ? Imf::FLOAT : Imf::HALF;
  const Imf::PixelType given = halves.empty() ? Imf::FLOAT : Imf::HALF;
  char* base = halves.empty() ? reinterpret_cast<char*>(const_cast<float*>(linear.pixels.data()))
                              : reinterpret_cast<char*>(halves.data());
  const size_t sample = halves.empty() ? sizeof(float) : sizeof(Imath::half);
  Imf::FrameBuffer buffer;
  for (int c = 0; c < 4; ++c) {
    header.channels().insert(kChannels[c], Imf::Channel(type));
    buffer.insert(kChannels[c], Imf::Slice(given, base + c * sample, 4 * sample,
                                           4 * sample * size_t(linear.width)));
  }
  for (const PassImage& p : passes) {
    const size_t n = p.channels.size();
    char* values = reinterpret_cast<char*>(const_cast<float*>(p.values.data()));
    for (size_t c = 0; c < n; ++c) {
      header.channels().insert(p.channels[c], Imf::Channel(Imf::FLOAT));
      buffer.insert(p.channels[c], Imf::Slice(Imf::FLOAT, values + c * sizeof(float),
                                              n * sizeof(float), n * sizeof(float) * p.width));
    }
  }
  if (piz) return encode_piz_exr(header, buffer);
  ExrMemoryStream stream;
  {
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(buffer);
    file.writePixels(linear.height);
  }  // the destructor writes the line offset table
  return stream.take();
}

ImageRGBA read_exr_file(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    const int width = dw.max.x - dw.min.x + 1, height = dw.max.y - dw.min.y + 1;
    const Imf::ChannelList& channels = file.header().channels();
    for (int c = 0; c < 3; ++c)
      if (!channels.findChannel(kChannels[c]))
        throw std::runtime_error(std::string("expected RGB(A), found no ") + kChannels[c] +
                                 " channel");
    ImageRGBA img(width, height);
    Imf::FrameBuffer buffer;
    const size_t pixel = 4 * sizeof(float);
    // The buffer's origin is the data window's corner, so pixel (min.x, min.y) lands at index 0.
    const std::ptrdiff_t origin =
        (std::ptrdiff_t(dw.min.y) * width + dw.min.x) * std::ptrdiff_t(pixel);
    char* base = reinterpret_cast<char*>(img.pixels.data()) - origin;
    for (int c = 0; c < 4; ++c)
      buffer.insert(kChannels[c],
                    Imf::Slice(Imf::FLOAT, base + c * sizeof(float), pixel, pixel * width, 1, 1,
                               c == 3 ? 1.0 : 0.0));  // a missing A reads as opaque
    file.setFrameBuffer(buffer);
    file.readPixels(dw.min.y, dw.max.y);
    return img;
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot read " + path + ": " + e.what());
  }
}

std::vector<float> read_exr_channel(const std::string& path, const std::string& channel) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    const int width = dw.max.x - dw.min.x + 1, height = dw.max.y - dw.min.y + 1;
    if (!file.header().channels().findChannel(channel))
      throw std::runtime_error("no channel '" + channel + "'");
    std::vector<float> values(size_t(width) * height);
    const std::ptrdiff_t origin =
        (std::ptrdiff_t(dw.min.y) * width + dw.min.x) * std::ptrdiff_t(sizeof(float));
    Imf::FrameBuffer buffer;
    buffer.insert(channel, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()) - origin,
                                      sizeof(float), sizeof(float) * size_t(width)));
    file.setFrameBuffer(buffer);
    file.readPixels(dw.min.y, dw.max.y);
    return values;
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot read " + path + ": " + e.what());
  }
}

std::map<std::string, std::string> read_exr_strings(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    std::map<std::string, std::string> strings;
    for (auto it = file.header().begin(); it != file.header().end(); ++it)
      if (auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
        strings[it.name()] = s->value();
    return strings;
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot read " + path + ": " + e.what());
  }
}

}  // namespace sdfreel
