#pragma once
// An Imf::OStream into a byte vector: frames are encoded in memory, then written by
// write_file_atomic, which checks every write (a full disk never publishes a short frame).
#include <OpenEXR/ImfIO.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace sdfreel {

class ExrMemoryStream : public Imf::OStream {
 public:
  ExrMemoryStream() : Imf::OStream("memory") {}
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

}  // namespace sdfreel
