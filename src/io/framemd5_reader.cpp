#include "io/framemd5_reader.h"

#include <cctype>
#include <charconv>
#include <sstream>
#include <vector>

namespace sdfreel {

namespace {

std::string trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string f;
  while (std::getline(in, f, ',')) fields.push_back(trim(f));
  return fields;
}

// A whole decimal integer (optional minus sign), nothing else; false when it does not fit
// (from_chars reports overflow instead of wrapping).
bool parse_int(const std::string& s, int64_t& out) {
  const char* end = s.data() + s.size();
  const auto [p, ec] = std::from_chars(s.data(), end, out);
  return !s.empty() && ec == std::errc() && p == end;
}

bool is_md5(const std::string& s) {
  if (s.size() != 32) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c)) && (c < 'a' || c > 'f')) return false;
  return true;
}

[[noreturn]] void fail(int line, const std::string& what) {
  throw Framemd5Error("line " + std::to_string(line) + ": " + what);
}

}  // namespace

Framemd5 parse_framemd5(const std::string& text) {
  Framemd5 out;
  std::stringstream in(text);
  std::string raw;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const std::string s = trim(raw);
    if (s.empty()) continue;
    if (s[0] == '#') {
      if (s.rfind("#hash:", 0) == 0) out.hash = trim(s.substr(6));
      continue;
    }
    const std::vector<std::string> f = split_commas(s);
    if (f.size() != 6)
      fail(line,
           "expected 6 comma-separated fields (stream, dts, pts, duration, size, hash), got " +
               std::to_string(f.size()));
    int64_t stream = 0, dts = 0, pts = 0, duration = 0, size = 0;
    if (!parse_int(f[0], stream) || !parse_int(f[1], dts) || !parse_int(f[2], pts) ||
        !parse_int(f[3], duration) || !parse_int(f[4], size))
      fail(line, "stream, dts, pts, duration and size must be whole numbers");
    if (!is_md5(f[5])) fail(line, "'" + f[5] + "' is not an MD5 (32 lowercase hex digits)");
    if (stream != 0) continue;  // only the video stream is compared
    if (pts < 0) fail(line, "negative pts " + f[2]);
    if (!out.frames.emplace(pts, Framemd5Frame{size, f[5]}).second)
      fail(line, "pts " + f[2] + " listed twice");
  }
  if (out.hash != "MD5") fail(0, "hash '" + out.hash + "' is not MD5 (ffmpeg -hash md5)");
  if (out.frames.empty()) throw Framemd5Error("no frame lines");
  return out;
}

}  // namespace sdfreel
