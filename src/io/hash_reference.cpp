#include "io/hash_reference.h"

#include <sys/stat.h>

#include <climits>
#include <fstream>
#include <sstream>

#include "io/framemd5_reader.h"

namespace sdfreel {

namespace {

// A framemd5 of a 10-hour 60 fps video is about 30 MB: 256 MiB is far above any real reference.
constexpr off_t kMaxReferenceBytes = off_t(256) << 20;

std::string read_reference_text(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw HashReferenceError(path + ": no such file");
  if (!S_ISREG(st.st_mode)) throw HashReferenceError(path + ": not a regular file");
  if (st.st_size > kMaxReferenceBytes)
    throw HashReferenceError(path + ": larger than 256 MiB, not a manifest or framemd5");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw HashReferenceError(path + ": cannot be read");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

HashReference from_manifest(const std::string& path, const std::string& text) {
  Manifest m;
  try {
    m = manifest_from_json(text);
  } catch (const std::exception& e) {
    throw HashReferenceError(path + ": not a valid sdfreel manifest.json (" + e.what() + ")");
  }
  HashReference r{"manifest.json", m.header, {}};
  for (const auto& [i, f] : m.frames) r.frames[i] = {f.display_md5, f.linear_hash, -1};
  return r;
}

HashReference from_framemd5(const std::string& path, const std::string& text) {
  Framemd5 f;
  try {
    f = parse_framemd5(text);
  } catch (const Framemd5Error& e) {
    throw HashReferenceError(path +
                             ": expected a manifest.json (a JSON object written by sdfreel render) "
                             "or a framemd5 ('#' header lines, then 'stream, dts, pts, duration, "
                             "size, md5' lines); as a framemd5, " +
                             e.what());
  }
  HashReference r{"framemd5", std::nullopt, {}};
  for (const auto& [pts, frame] : f.frames) {
    if (pts > INT_MAX)
      throw HashReferenceError(path + ": pts " + std::to_string(pts) + " too large");
    r.frames[int(pts)] = {frame.md5, "", frame.size};
  }
  return r;
}

}  // namespace

HashReference read_hash_reference(const std::string& path) {
  const std::string text = read_reference_text(path);
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{') return from_manifest(path, text);
  return from_framemd5(path, text);
}

}  // namespace sdfreel
