#include "timeline/toml_errors.h"

namespace sdfreel {

std::string toml_error_message(const std::string& description) {
  auto has = [&](const char* s) { return description.find(s) != std::string::npos; };
  // A string left open runs into the end of its line (a control character to toml++) or of the
  // file.
  if (has("while parsing string") && (has("control character") || has("end-of-file")))
    return "a string is not closed: add the missing closing quote (\") before the end of the line "
           "(toml++: " +
           description + ")";
  return description;
}

}  // namespace sdfreel
