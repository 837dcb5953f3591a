#include "timeline/toml_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "timeline/suggest.h"
#include "timeline/timeline.h"

namespace sdfreel {
namespace {

bool before(const toml::source_position& a, const toml::source_position& b) {
  return a.line != b.line ? a.line < b.line : a.column < b.column;
}

}  // namespace

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    default:
      return "nothing";
  }
}

std::vector<std::pair<const toml::key*, const toml::node*>> keys_in_file_order(
    const toml::table& table) {
  std::vector<std::pair<const toml::key*, const toml::node*>> keys;
  for (auto&& [key, node] : table) keys.emplace_back(&key, &node);
  std::stable_sort(keys.begin(), keys.end(), [](const auto& a, const auto& b) {
    return before(a.first->source().begin, b.first->source().begin);
  });
  return keys;
}

std::string join(const std::vector<std::string>& names, const std::string& last_sep) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? last_sep : ", ") + names[i];
  return out;
}

std::string format_number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

void TomlReader::fail(const toml::source_region& where, const std::string& what) const {
  throw InputError(file_, int(where.begin.line), int(where.begin.column), what);
}

void TomlReader::check_keys(const toml::table& table, const std::string& where,
                            const std::vector<std::string>& allowed) const {
  for (const auto& [key, node] : keys_in_file_order(table)) {
    const std::string name(key->str());
    if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
    const char* kind = node->is_table() && where.empty() ? "table" : "key";
    fail(key->source(), std::string("unknown ") + kind + " '" + name + "'" +
                            (where.empty() ? "" : " in " + where) + did_you_mean(name, allowed));
  }
}

const toml::node& TomlReader::require(const toml::table& table, const char* key,
                                      const std::string& where) const {
  if (const toml::node* n = table.get(key)) return *n;
  fail(table.source(), std::string("missing key '") + key + "' in " + where);
}

void TomlReader::wrong_type(const toml::node& n, const std::string& name,
                            const std::string& expected) const {
  fail(n, name + " must be " + expected + ", not " + type_name(n));
}

const toml::table& TomlReader::table(const toml::node& n, const std::string& name) const {
  if (const toml::table* t = n.as_table()) return *t;
  wrong_type(n, name, "a table");
}

const toml::array& TomlReader::array(const toml::node& n, const std::string& name) const {
  if (const toml::array* a = n.as_array()) return *a;
  wrong_type(n, name, "an array");
}

std::string TomlReader::string(const toml::node& n, const std::string& name) const {
  if (const auto* s = n.as_string()) return s->get();
  wrong_type(n, name, "a string");
}

int64_t TomlReader::integer(const toml::node& n, const std::string& name) const {
  if (const auto* i = n.as_integer()) return i->get();
  wrong_type(n, name, "an integer");
}

int64_t TomlReader::integer_in(const toml::node& n, const std::string& name, int64_t lo,
                               int64_t hi) const {
  const int64_t v = integer(n, name);
  if (v < lo || v > hi)
    fail(n, name + " " + std::to_string(v) + " is outside " + std::to_string(lo) + ".." +
                std::to_string(hi));
  return v;
}

double TomlReader::number(const toml::node& n, const std::string& name) const {
  if (const auto* i = n.as_integer()) return double(i->get());
  const auto* f = n.as_floating_point();
  if (!f) wrong_type(n, name, "a number");
  const double v = f->get();
  if (!std::isfinite(v)) fail(n, name + " must be a finite number, not " + format_number(v));
  return v;
}

std::vector<double> TomlReader::numbers(const toml::node& n, const std::string& name,
                                        size_t count) const {
  if (count == 1) {
    if (n.is_array()) fail(n, name + " must be a number, not an array");
    return {number(n, name)};
  }
  const std::string expected = "an array of " + std::to_string(count) + " numbers";
  const toml::array* a = n.as_array();
  if (!a) wrong_type(n, name, expected);
  if (a->size() != count)
    fail(n, name + " must be " + expected + ", not of " + std::to_string(a->size()));
  std::vector<double> out;
  for (size_t i = 0; i < count; ++i)
    out.push_back(number(*a->get(i), name + "[" + std::to_string(i) + "]"));
  return out;
}

glm::dvec3 TomlReader::point(const toml::node& n, const std::string& name) const {
  std::vector<double> v = numbers(n, name, 3);
  return {v[0], v[1], v[2]};
}

std::string TomlReader::choice(const toml::node& n, const std::string& name,
                               const std::vector<std::string>& choices) const {
  std::string v = string(n, name);
  if (std::find(choices.begin(), choices.end(), v) != choices.end()) return v;
  fail(n, name + " '" + v + "' is not one of " + join(choices, " or ") + did_you_mean(v, choices));
}

}  // namespace sdfreel
