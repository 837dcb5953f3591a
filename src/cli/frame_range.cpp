#include "cli/frame_range.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "pipeline/errors.h"

namespace sdfreel {

namespace {

int parse_index(const std::string& s, const std::string& spec) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos || s.size() > 9)
    throw UsageError("--frames '" + spec + "': '" + s + "' is not a frame number");
  return std::atoi(s.c_str());
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
  long i = -1, n = -1;
  char slash = 0, extra = 0;
  std::stringstream ss(spec);
  ss >> i >> slash >> n;
  if (!ss || slash != '/' || (ss >> extra) || n < 1 || i < 0 || i >= n)
    throw UsageError("--shard '" + spec + "': expected I/N with 0 <= I < N");
  const size_t total = frames.size();
  const size_t begin = total * size_t(i) / size_t(n), end = total * size_t(i + 1) / size_t(n);
  return std::vector<int>(frames.begin() + begin, frames.begin() + end);
}

}  // namespace sdfreel
