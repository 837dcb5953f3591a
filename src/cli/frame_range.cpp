#include "cli/frame_range.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "cli/option_numbers.h"
#include "pipeline/errors.h"

namespace sdfreel {

namespace {

int parse_index(const std::string& s, const std::string& spec) {
  // Frame counts are below 1e8 (the timeline's limit); larger numbers are refused as too large.
  const auto v = parse_count(s, 999999999);
  if (!v) throw UsageError("--frames '" + spec + "': '" + s + "' is not a frame number");
  return int(*v);
}

}  // namespace

std::vector<int> parse_frame_list(const std::string& spec, int count) {
  std::vector<int> out;
  std::stringstream ss(spec);
  std::string part;
  while (std::getline(ss, part, ',')) {
    const size_t dash = part.find('-');
    int a = 0, b = 0;
    if (dash == std::string::npos) {
      a = b = parse_index(part, spec);
    } else {
      a = parse_index(part.substr(0, dash), spec);
      b = parse_index(part.substr(dash + 1), spec);
      if (b < a) throw UsageError("--frames '" + spec + "': range " + part + " runs backwards");
    }
    if (b >= count)
      throw UsageError("--frames '" + spec + "': frame " + std::to_string(b) +
                       " is past the last frame (" + std::to_string(count - 1) + ")");
    for (int i = a; i <= b; ++i) out.push_back(i);
  }
  if (out.empty()) throw UsageError("--frames '" + spec + "' selects no frame");
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> shard_of(const std::vector<int>& frames, const std::string& spec) {
  const size_t slash = spec.find('/');
  const std::string_view text(spec);
  const auto i =
      slash == std::string::npos ? std::nullopt : parse_count(text.substr(0, slash), INT64_MAX);
  const auto n =
      slash == std::string::npos ? std::nullopt : parse_count(text.substr(slash + 1), INT64_MAX);
  if (!i || !n || *n < 1 || *i >= *n)
    throw UsageError("--shard '" + spec + "': expected I/N with 0 <= I < N");
  // 128-bit products: total * I cannot overflow even for I and N near 2^63.
  using u128 = unsigned __int128;
  const u128 total = frames.size();
  const size_t begin = size_t(total * u128(*i) / u128(*n));
  const size_t end = size_t(total * (u128(*i) + 1) / u128(*n));
  return std::vector<int>(frames.begin() + std::ptrdiff_t(begin),
                          frames.begin() + std::ptrdiff_t(end));
}

}  // namespace sdfreel
