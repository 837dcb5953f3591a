#pragma once
// Strict, overflow-safe numbers of command-line options: digits only, no sign, no spaces, and a
// value that does not fit is an error (exit 2), never a wrapped or clamped number.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace sdfreel {

// "123" -> 123; nullopt for empty text, any non-digit, or a value above `max`.
std::optional<int64_t> parse_count(std::string_view text, int64_t max);

struct Resolution {
  int64_t width = 0, height = 0;  // wide: the caller range-checks (check_resolution)
};
// `--resolution WxH`. Throws UsageError for bad syntax or a side beyond int64.
Resolution parse_resolution_option(const std::string& spec);

}  // namespace sdfreel
