#pragma once
// Typed reading of toml++ nodes for the timeline parser: every missing key, wrong type, unknown
// key or non-finite number becomes an InputError that points at the offending key or value.
#include <toml++/toml.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

namespace sdfreel {

// Keys of a table in the order they appear in the file, so the first mistake is reported first.
std::vector<std::pair<const toml::key*, const toml::node*>> keys_in_file_order(
    const toml::table& table);

// "an integer", "a string", ...: a node's type for messages.
std::string type_name(const toml::node& n);

// "a, b or c" (last_sep " or ") or "a, b, c" (last_sep ", ").
std::string join(const std::vector<std::string>& names, const std::string& last_sep);

// Shortest round-trip text of a number, for messages ("0.5", "1e+30", "nan").
std::string format_number(double v);

class TomlReader {
 public:
  explicit TomlReader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const toml::source_region& where, const std::string& what) const;
  [[noreturn]] void fail(const toml::node& at, const std::string& what) const {
    fail(at.source(), what);
  }

  // Refuses keys not in `allowed`, suggesting the closest. `where` names the table in messages,
  // e.g. "[video]" or "camera.keys[2]".
  void check_keys(const toml::table& table, const std::string& where,
                  const std::vector<std::string>& allowed) const;
  // The value of a key that must be present.
  const toml::node& require(const toml::table& table, const char* key,
                            const std::string& where) const;

  // Conversions; `name` is the dotted key path used in messages ("video.fps").
  const toml::table& table(const toml::node& n, const std::string& name) const;
  const toml::array& array(const toml::node& n, const std::string& name) const;
  std::string string(const toml::node& n, const std::string& name) const;
  int64_t integer(const toml::node& n, const std::string& name) const;
  int64_t integer_in(const toml::node& n, const std::string& name, int64_t lo, int64_t hi) const;
  double number(const toml::node& n, const std::string& name) const;  // integer or float, finite
  // Exactly `count` numbers; count 1 takes a bare number, larger counts an array.
  std::vector<double> numbers(const toml::node& n, const std::string& name, size_t count) const;
  glm::dvec3 point(const toml::node& n, const std::string& name) const;
  // A string that must be one of `choices`; the error names them and the closest one.
  std::string choice(const toml::node& n, const std::string& name,
                     const std::vector<std::string>& choices) const;

 private:
  [[noreturn]] void wrong_type(const toml::node& n, const std::string& name,
                               const std::string& expected) const;
  std::string file_;
};

}  // namespace sdfreel
