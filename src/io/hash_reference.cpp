#include "io/hash_reference.h"

#include <climits>

#include "io/bounded_read.h"
#include "io/framemd5_reader.h"

namespace sdfreel {

namespace {

// Special files, huge files and missing files are bad input, never a hang or an unbounded read.
std::string read_reference_text(const std::string& path) {
  std::optional<std::string> text;
  try {
    text = read_regular_file(path, kMaxManifestBytes);
  } catch (const std::exception& e) {
    throw HashReferenceError(e.what());
  }
  if (!text) throw HashReferenceError(path + ": no such file");
  return *text;
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
