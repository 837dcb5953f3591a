#pragma once
// Exit-status classes: UsageError -> 2 (bad usage or input, nothing written), RenderError -> 1.
#include <stdexcept>
#include <string>

namespace sdfreel {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct RenderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace sdfreel
