#pragma once
// Strict UTF-8 check (no overlong forms, no surrogates, nothing past U+10FFFF), so that a timeline
// that is not UTF-8 is refused with the position of its first bad byte.
#include <optional>
#include <string_view>

namespace sdfreel {

struct TextPosition {
  int line = 1, column = 1;  // 1-based; column counts code points
};

// Position of the first byte that is not part of a valid UTF-8 sequence, or nothing.
std::optional<TextPosition> find_invalid_utf8(std::string_view text);

}  // namespace sdfreel
