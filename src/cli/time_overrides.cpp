#include "cli/time_overrides.h"

#include <cmath>
#include <numeric>

#include "cli/option_numbers.h"
#include "pipeline/errors.h"

namespace sdfreel {

namespace {

constexpr double kMaxFrames = 1e8;  // as a timeline's [video] allows

bool number(const std::string& s, double& out) {
  try {
    size_t used = 0;
    out = std::stod(s, &used);
    return used == s.size() && std::isfinite(out);
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

Rational parse_fps_option(const std::string& text, const std::string& option) {
  const size_t slash = text.find('/');
  const std::optional<int64_t> num = parse_count(text.substr(0, slash), 1000000000);
  const std::optional<int64_t> den =
      slash == std::string::npos ? 1 : parse_count(text.substr(slash + 1), 1000000);
  if (!num || !den || *num == 0 || *den == 0)
    throw UsageError(option + " " + text +
                     ": frames per second are a whole number or N/D, e.g. 24 or 30000/1001");
  const int64_t g = std::gcd(*num, *den);
  return {*num / g, *den / g};
}

void apply_time_overrides(const std::string& fps, double duration, Timeline& tl) {
  if (!fps.empty()) tl.fps = parse_fps_option(fps);
  if (duration != 0.0) {
    if (!(duration > 0.0) || !std::isfinite(duration))
      throw UsageError("--duration " + std::to_string(duration) + ": seconds, more than 0");
    tl.duration = duration;
  }
  if (tl.duration * tl.fps.value() > kMaxFrames)
    throw UsageError("--fps and --duration make more than 100000000 frames");
}

std::vector<int> frames_in_time_range(const std::string& range, const Timeline& tl) {
  const size_t dash = range.find('-', 1);  // after a leading sign
  double a = 0.0, b = 0.0;
  if (dash == std::string::npos || !number(range.substr(0, dash), a) ||
      !number(range.substr(dash + 1), b) || a < 0.0 || b < a)
    throw UsageError("--time-range " + range +
                     ": A-B in seconds of video, 0 <= A <= B, e.g. 2.5-4");
  const double fps = tl.fps.value();
  // Frame i's time is i / fps; a small slack keeps a boundary that is a frame's time inside.
  const int first = std::max(0, int(std::ceil(a * fps - 1e-9)));
  const int last = std::min(tl.frame_count() - 1, int(std::floor(b * fps + 1e-9)));
  if (first > last)
    throw UsageError("--time-range " + range + " holds no frame of the timeline (0 to " +
                     std::to_string(double(tl.frame_count() - 1) / fps) + " s)");
  std::vector<int> frames;
  for (int i = first; i <= last; ++i) frames.push_back(i);
  return frames;
}

}  // namespace sdfreel
