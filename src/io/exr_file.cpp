#include "io/exr_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace sdfreel {

namespace {

// An Imf::OStream into a byte vector: frames are encoded in memory, then written by
// write_file_atomic, which checks every write (a full disk never publishes a short frame).
class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (pos_ + size_t(n) > bytes_.size()) bytes_.resize(pos_ + size_t(n));
    std::copy(c, c + n, bytes_.begin() + std::ptrdiff_t(pos_));
    pos_ += size_t(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = size_t(pos); }
  std::vector<char> take() { return std::move(bytes_); }

 private:
  std::vector<char> bytes_;
  size_t pos_ = 0;
};

constexpr const char* kChannels[4] = {"R", "G", "B", "A"};

}  // namespace

std::vector<char> encode_exr(const ImageRGBA& linear,
                             const std::map<std::string, std::string>& metadata) {
  Imf::Header header(linear.width, linear.height);
  header.compression() = Imf::PIZ_COMPRESSION;  // lossless; faster and smaller than zip here
  for (const auto& [key, value] : metadata)
    header.insert("sdfreel:" + key, Imf::StringAttribute(value));
  // OpenEXR writes a half channel from half data only: round here (Imath, nearest even).
  std::vector<Imath::half> halves(linear.pixels.begin(), linear.pixels.end());
  Imf::FrameBuffer buffer;
  const size_t pixel = 4 * sizeof(Imath::half);
  for (int c = 0; c < 4; ++c) {
    header.channels().insert(kChannels[c], Imf::Channel(Imf::HALF));
    buffer.insert(kChannels[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves.data() + c),
                                           pixel, pixel * size_t(linear.width)));
  }
  MemoryStream stream;
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
