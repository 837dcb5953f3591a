#pragma once
// toml++'s parse errors in words that say what to fix, where its own say how the parser failed.
#include <string>

namespace sdfreel {

// The message for a toml::parse_error's description: toml++'s, or plainer advice with it.
std::string toml_error_message(const std::string& description);

}  // namespace sdfreel
