#include "cli/option_numbers.h"

#include <charconv>

#include "pipeline/errors.h"
#include "timeline/rules.h"  // kMaxImageSize

namespace sdfreel {

std::optional<int64_t> parse_count(std::string_view text, int64_t max) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos)
    return std::nullopt;
  uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || v > uint64_t(max))
    return std::nullopt;
  return int64_t(v);
}

Resolution parse_resolution_option(const std::string& spec) {
  const size_t x = spec.find('x');
  const std::string usage = "--resolution '" + spec + "': expected WxH, e.g. 64x36";
  if (x == std::string::npos) throw UsageError(usage);
  // Parsed wide, then range-checked: 4294967298x2 is refused, not wrapped to 2x2.
  const auto w = parse_count(std::string_view(spec).substr(0, x), INT64_MAX);
  const auto h = parse_count(std::string_view(spec).substr(x + 1), INT64_MAX);
  if (!w || !h) {
    const bool digits = spec.find_first_not_of("0123456789x") == std::string::npos &&
                        spec.find('x', x + 1) == std::string::npos && x > 0 && x + 1 < spec.size();
    throw UsageError(digits ? "--resolution '" + spec + "': a side is too large (at most " +
                                  std::to_string(kMaxImageSize) + ")"
                            : usage);
  }
  return {*w, *h};
}

}  // namespace sdfreel
