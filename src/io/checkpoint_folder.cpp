#include "io/checkpoint_folder.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/atomic_file.h"
#include "io/cache_file.h"

namespace sdfreel {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'S', 'D', 'F', 'R', 'B', 'U', 'F', '2'};

struct Header {  // after the magic and the key
  int32_t next_frame, width, height, cube_size;
  uint32_t present;  // bit k: buffer k (PassKind) is in the payload
  uint32_t reserved;
  uint64_t payload_bytes, checksum;
};

constexpr size_t kCubeA = 4;

// Floats of buffer k in a state of this size: RGBA texels, six faces for Cube A.
uint64_t buffer_floats(size_t k, const Header& h) {
  return k == kCubeA ? uint64_t(uint32_t(h.cube_size)) * uint64_t(uint32_t(h.cube_size)) * 4 * 6
                     : uint64_t(uint32_t(h.width)) * uint64_t(uint32_t(h.height)) * 4;
}

template <typename T>
void append(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// Reads a T at `at`, advancing it; false past the end.
template <typename T>
bool take(const std::string& in, size_t& at, T& v) {
  if (in.size() - at < sizeof v) return false;
  std::memcpy(&v, in.data() + at, sizeof v);
  at += sizeof v;
  return true;
}

std::string read_whole(const std::string& path, size_t limit) {
  std::ifstream f(path, std::ios::binary);
  std::string bytes;
  if (!f) return bytes;
  bytes.resize(limit);
  f.read(bytes.data(), std::streamsize(limit));
  bytes.resize(size_t(f.gcount()));
  return bytes;
}

}  // namespace

std::string encode_checkpoint(const BufferState& s, const std::string& key) {
  std::string payload;
  uint32_t present = 0;
  for (size_t k = 0; k < s.buffers.size(); ++k) {
    if (s.buffers[k].empty()) continue;
    present |= 1u << k;
    payload.append(reinterpret_cast<const char*>(s.buffers[k].data()),
                   s.buffers[k].size() * sizeof(float));
  }
  std::string out(kMagic, sizeof kMagic);
  append(out, uint64_t(key.size()));
  out += key;
  append(out, Header{s.next_frame, s.width, s.height, s.cube_size, present, 0, payload.size(),
                     checksum64(payload.data(), payload.size())});
  return out + payload;
}

std::string decode_checkpoint(const std::string& bytes, const std::string& key, BufferState& s,
                              bool header_only) {
  size_t at = 0;
  if (bytes.compare(0, sizeof kMagic, kMagic, sizeof kMagic) != 0) return "not a checkpoint";
  at = sizeof kMagic;
  uint64_t key_size = 0;
  if (!take(bytes, at, key_size) || key_size != key.size() ||
      bytes.compare(at, key.size(), key) != 0)
    return "made by a render of other settings";
  at += key.size();
  Header h{};
  if (!take(bytes, at, h)) return "truncated";
  uint64_t floats = 0;
  for (size_t k = 0; k < s.buffers.size(); ++k)
    if (h.present & (1u << k)) {
      if (buffer_floats(k, h) == 0) return "a damaged header";  // Cube A present, of size 0
      floats += buffer_floats(k, h);
    }
  if (h.width <= 0 || h.height <= 0 || h.cube_size < 0 || h.next_frame < 0 || h.present >= 32 ||
      h.reserved != 0 || h.width > 65536 || h.height > 65536 || h.cube_size > 65536 ||
      h.payload_bytes != floats * sizeof(float))
    return "a damaged header";
  if (header_only) {
    s.next_frame = h.next_frame, s.width = h.width, s.height = h.height, s.cube_size = h.cube_size;
    return "";
  }
  if (bytes.size() - at != h.payload_bytes) return "truncated";
  if (checksum64(bytes.data() + at, h.payload_bytes) != h.checksum) return "a wrong checksum";
  s = BufferState{h.next_frame, h.width, h.height, h.cube_size, {}};
  for (size_t k = 0; k < s.buffers.size(); ++k) {
    if (!(h.present & (1u << k))) continue;
    const size_t floats_k = size_t(buffer_floats(k, h));
    s.buffers[k].resize(floats_k);
    std::memcpy(s.buffers[k].data(), bytes.data() + at, floats_k * sizeof(float));
    at += floats_k * sizeof(float);
  }
  return "";
}

CheckpointFolder::CheckpointFolder(std::string dir, std::string key, int every, int frame_count,
                                   bool writable)
    : dir_(std::move(dir)),
      key_(std::move(key)),
      every_(every),
      frame_count_(frame_count),
      writable_(writable) {}

std::string CheckpointFolder::path(int next_frame) const {
  char name[32];
  std::snprintf(name, sizeof name, "buffers-%05d.ckpt", next_frame);
  return dir_ + "/" + name;
}

std::optional<BufferState> CheckpointFolder::latest(int from, int to, int width, int height) {
  for (int f = to / every_ * every_; f >= from && f > 0; f -= every_) {
    const std::string file = path(f);
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) continue;
    BufferState s;
    std::string why = decode_checkpoint(read_whole(file, size_t(fs::file_size(file, ec))), key_, s);
    if (why.empty() && (s.next_frame != f || s.width != width || s.height != height))
      why = "another frame or size than its name says";
    if (why.empty()) return s;
    std::fprintf(stderr, "sdfreel: warning: checkpoint %s is not used: %s\n", file.c_str(),
                 why.c_str());
    rejected_.insert(f);
  }
  return std::nullopt;
}

bool CheckpointFolder::has(int next_frame) {
  if (!writable_ || next_frame >= frame_count_) return true;
  if (rejected_.count(next_frame)) return false;
  BufferState s;
  const std::string head = read_whole(path(next_frame), 4096 + key_.size());
  return decode_checkpoint(head, key_, s, true).empty() && s.next_frame == next_frame;
}

void CheckpointFolder::save(const BufferState& state) {
  if (!writable_) return;
  try {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    write_file_atomic(path(state.next_frame), encode_checkpoint(state, key_));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sdfreel: warning: checkpoint not kept (%s): later starts replay more\n",
                 e.what());
  }
}

}  // namespace sdfreel
