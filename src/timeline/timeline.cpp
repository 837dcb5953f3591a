// Timeline's small methods, InputError, and the checks re-run after command-line overrides.
#include "timeline/timeline.h"

#include <algorithm>
#include <cmath>

#include "timeline/rules.h"
#include "timeline/video_codec_rules.h"

namespace sdfreel {

InputError::InputError(std::string file_, int line_, int column_, const std::string& what)
    : std::runtime_error(what), file(std::move(file_)), line(line_), column(column_) {}

std::string InputError::formatted() const {
  std::string out = file;
  if (line > 0) {
    out += ":" + std::to_string(line);
    if (column > 0) out += ":" + std::to_string(column);
  }
  return out + ": error: " + what();
}

int Timeline::frame_count() const {
  return std::max(1, int(std::llround(duration * fps.value())));
}

AdaptiveSampling Timeline::adaptive_at_size() const {
  if (!adaptive.enabled) return adaptive;
  AdaptiveSampling a = adaptive_preset(quality, width, height);
  if (adaptive_given.minimum) a.minimum = adaptive.minimum;
  if (adaptive_given.maximum) a.maximum = adaptive.maximum;
  if (adaptive_given.threshold) a.threshold = adaptive.threshold;
  // A given bound wins over the preset's other one (the file's pair was checked when parsed).
  if (a.maximum < a.minimum) {
    if (adaptive_given.minimum)
      a.maximum = a.minimum;
    else
      a.minimum = a.maximum;
  }
  return a;
}

double Timeline::video_time(int frame) const {
  // One rounding only: frame * den is an exact integer (the parser bounds num and den).
  return double(int64_t(frame) * fps.den) / double(fps.num);
}

double Timeline::scene_time(int frame) const {
  const double t = video_time(frame);
  return time ? time->sample(t)[0] : t;
}

std::string check_resolution(int64_t width, int64_t height) {
  auto ok = [](int64_t v) { return v >= 1 && v <= kMaxImageSize; };
  if (ok(width) && ok(height)) return "";
  return "resolution " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1.." +
         std::to_string(kMaxImageSize);
}

std::string check_samples(int64_t samples) {
  if (samples >= 1 && samples <= kMaxSamples) return "";
  return "samples " + std::to_string(samples) + " is outside 1.." + std::to_string(kMaxSamples);
}

std::string check_codec_size(const std::string& codec, int64_t width, int64_t height) {
  const VideoCodecRule* rule = find_video_codec_rule(codec);
  if (!rule || !rule->even_size || (width % 2 == 0 && height % 2 == 0)) return "";
  // Round odd sizes up: the result stays within 1..16384 because 16384 is even.
  auto even = [](int64_t v) { return v % 2 == 0 ? v : v + 1; };
  return "resolution " + std::to_string(width) + "x" + std::to_string(height) +
         " has an odd side, but codec " + codec + " (" + rule->pix_fmt +
         ") needs an even width and height: use " + std::to_string(even(width)) + "x" +
         std::to_string(even(height));
}

void validate_overrides(const Timeline& tl, bool makes_video) {
  for (const std::string& problem :
       {check_resolution(tl.width, tl.height), check_samples(tl.samples)})
    if (!problem.empty()) throw InputError(tl.path, 0, 0, problem);
  if (!makes_video || tl.video.empty()) return;
  if (std::string problem = check_codec_size(tl.codec, tl.width, tl.height); !problem.empty())
    throw InputError(tl.path, tl.resolution_line, tl.resolution_column, problem);
}

}  // namespace sdfreel
