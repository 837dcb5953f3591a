#include "backends/gl/shader_source.h"

#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

namespace sdfreel {

namespace {

std::string join_path(const std::string& dir, const std::string& file) {
  if (dir.empty()) return file;
  return dir.back() == '/' ? dir + file : dir + "/" + file;
}

// `#include "path"` (spaces allowed around #, include and the path; a trailing // comment too).
// Returns true and sets path for include lines; sets bad for malformed ones.
bool parse_include(const std::string& line, std::string& path, bool& bad) {
  size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '#') return false;
  i = line.find_first_not_of(" \t", i + 1);
  if (i == std::string::npos || line.compare(i, 7, "include") != 0) return false;
  i = line.find_first_not_of(" \t", i + 7);
  const size_t close = i == std::string::npos ? i : line.find('"', i + 1);
  bad = i == std::string::npos || line[i] != '"' || close == std::string::npos;
  if (bad) return true;
  path = line.substr(i + 1, close - i - 1);
  const size_t rest = line.find_first_not_of(" \t", close + 1);
  bad = path.empty() || (rest != std::string::npos && line.compare(rest, 2, "//") != 0);
  return true;
}

bool is_version_line(const std::string& line) {
  size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '#') return false;
  i = line.find_first_not_of(" \t", i + 1);
  return i != std::string::npos && line.compare(i, 7, "version") == 0;
}

// The next line is line `line` of file `number` (see SHADER_LINE_BLOCK).
std::string line_directive(int number, int line) {
  return "#line " + std::to_string(number * SHADER_LINE_BLOCK + line) + " " +
         std::to_string(number) + "\n";
}

class Resolver {
 public:
  explicit Resolver(const std::string& dir) : dir_(dir) {}

  ShaderSource run(const std::string& file, const std::string& preamble) {
    out_.text = preamble;
    if (!preamble.empty() && preamble.back() != '\n') out_.text += '\n';
    add(file, "", 0);
    return out_;
  }

 private:
  void add(const std::string& file, const std::string& from, int from_line) {
    const std::string where =
        from.empty() ? "" : join_path(dir_, from) + ":" + std::to_string(from_line) + ": ";
    std::ifstream in(join_path(dir_, file));
    if (!in) throw ShaderError(where + "cannot read shader " + join_path(dir_, file));
    const int number = int(out_.files.size());
    out_.files.push_back(file);
    seen_.insert(file);
    out_.text += line_directive(number, 1);
    std::string line;
    int line_no = 0;
    while (std::getline(in, line)) {
      ++line_no;
      std::string path;
      bool bad = false;
      if (line_no >= SHADER_LINE_BLOCK)
        throw ShaderError(join_path(dir_, file) + ": more than " +
                          std::to_string(SHADER_LINE_BLOCK - 1) + " lines");
      if (is_version_line(line))
        throw ShaderError(join_path(dir_, file) + ":" + std::to_string(line_no) +
                          ": #version belongs to the driver's preamble; remove it");
      if (!parse_include(line, path, bad)) {
        out_.text += line;
        out_.text += '\n';
        continue;
      }
      if (bad)
        throw ShaderError(join_path(dir_, file) + ":" + std::to_string(line_no) +
                          ": malformed #include (expected #include \"path\")");
      if (!seen_.count(path)) add(path, file, line_no);
      // Back in this file: the next line is line_no + 1. The include line itself became empty.
      out_.text += line_directive(number, line_no + 1);
    }
  }

  std::string dir_;
  ShaderSource out_;
  std::set<std::string> seen_;
};

// Parses "N:L(C): " or "N:L: " at the start of a line; returns the length of the prefix or 0.
size_t parse_location(const std::string& line, int& file, int& row, int& col) {
  size_t i = 0;
  auto number = [&](int& v) {
    const size_t start = i;
    v = 0;
    while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i])) && i - start < 9)
      v = v * 10 + (line[i++] - '0');
    return i > start;
  };
  if (!number(file) || i >= line.size() || line[i++] != ':' || !number(row)) return 0;
  col = -1;
  if (i < line.size() && line[i] == '(') {
    ++i;
    if (!number(col) || i >= line.size() || line[i++] != ')') return 0;
  }
  if (i >= line.size() || line[i++] != ':') return 0;
  if (i < line.size() && line[i] == ' ') ++i;
  return i;
}

}  // namespace

ShaderSource load_shader_source(const std::string& dir, const std::string& file,
                                const std::string& preamble) {
  return Resolver(dir).run(file, preamble);
}

std::string map_shader_log(const std::string& log, const ShaderSource& source,
                           const std::string& dir) {
  std::istringstream in(log);
  std::string line, out;
  while (std::getline(in, line)) {
    int number = 0, row = 0, col = 0;
    const size_t prefix = parse_location(line, number, row, col);
    const int file = row / SHADER_LINE_BLOCK;  // the reported source number may be 0: ignore it
    if (prefix && file < int(source.files.size())) {
      out += join_path(dir, source.files[size_t(file)]) + ":" +
             std::to_string(row % SHADER_LINE_BLOCK);
      if (col >= 0) out += ":" + std::to_string(col);
      out += ": " + line.substr(prefix);
    } else {
      out += line;
    }
    out += '\n';
  }
  return out;
}

}  // namespace sdfreel
