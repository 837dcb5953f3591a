// load_timeline: read the file, refuse what the spec calls bad input, fill a Timeline.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <sstream>

#include "timeline/rules.h"
#include "timeline/sections.h"
#include "timeline/sha256.h"
#include "timeline/toml_errors.h"
#include "timeline/utf8.h"

namespace sdfreel {
namespace {

constexpr uint64_t kMaxFileBytes = 16u << 20;  // 16 MiB

std::string read_file(const std::string& path) {
  // O_NONBLOCK: opening a FIFO without a writer would otherwise block forever. Only regular files
  // are read: a FIFO, a device (/dev/zero) or a directory is refused before any byte is read.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
    throw InputError(path, 0, 0, std::string("cannot open the file: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw InputError(path, 0, 0,
                     S_ISDIR(st.st_mode) ? "cannot read: it is a directory"
                                         : "cannot read: not a regular file (a FIFO or device?)");
  }
  // Read in chunks and stop one byte past the limit: a huge file is refused without reading it all.
  std::string bytes;
  char chunk[1 << 16];
  ssize_t n = 0;
  while (bytes.size() <= kMaxFileBytes && (n = ::read(fd, chunk, sizeof chunk)) != 0) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    bytes.append(chunk, size_t(n));
  }
  ::close(fd);
  if (n < 0) throw InputError(path, 0, 0, "cannot read the file");
  if (bytes.size() > kMaxFileBytes)
    throw InputError(path, 0, 0, "the file is larger than 16 MiB; a timeline is a small text file");
  return bytes;
}

const toml::node* find(const toml::table& root, const char* table, const char* key) {
  const toml::table* t = root.get_as<toml::table>(table);
  return t ? t->get(key) : nullptr;
}

// Rules that involve more than one key, checked after every table has been read.
void check_across_tables(const TomlReader& r, const toml::table& root, const Timeline& tl,
                         const ColorChecker* color) {
  // h264's even sizes are checked when a video is made (validate_overrides): --no-video, still,
  // sheet and a partial frame range take any size.
  // A display-referred shader's display pixels are its PNG's: its EXR (their sRGB decoding, in
  // half floats) does not give them back bit for bit, so resume, encode and verify need the PNG.
  if (tl.shader_scene && tl.shader_scene->display_referred && !tl.write_png) {
    const toml::node* at = find(root, "output", "frames");
    r.fail(at ? at->source() : toml::source_region{},
           "output.frames of a display-referred shader must include \"png\" (its display "
           "pixels are kept there; [shader] output = \"linear\" renders without it)");
  }
  // The video's container must hold the codec: found here, not after the folder was made.
  if (std::string problem = check_video_name(tl.video, tl.codec); !problem.empty()) {
    const toml::node* at = find(root, "output", "video");
    r.fail(at ? at->source() : toml::source_region{}, problem);
  }
  if (color) {
    if (std::string problem = color->check(tl.color_config, tl.display, tl.view);
        !problem.empty()) {
      // The checker's message quotes the names it refused; point at the most specific one
      // (a bad view's message also names its display, a bad display's names its config).
      auto quoted = [&](const std::string& v) {
        return problem.find('"' + v + '"') != std::string::npos ||
               problem.find('\'' + v + '\'') != std::string::npos;
      };
      const char* key = quoted(tl.view) ? "view" : quoted(tl.display) ? "display" : "config";
      const toml::node* at = find(root, "color", key);
      const toml::table* section = root.get_as<toml::table>("color");
      r.fail(at ? at->source() : section ? section->source() : toml::source_region{}, problem);
    }
  }
}

// A key written above every table header (or with its header left out) lands at the top level:
// name the table it belongs in, instead of calling it unknown.
void check_top_level_keys(const TomlReader& r, const toml::table& root) {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> homes = {
      {"[video]",
       {"scene", "shader", "fps", "duration", "resolution", "samples", "adaptive", "quality",
        "seed"}},
      {"[output]", {"dir", "frames", "codec", "crf"}},
      {"[color]", {"config", "display", "view"}},
      {"[camera]", {"speed"}},
      {"[camera], [time] or a [params.NAME] table", {"keys", "interpolation"}},
  };
  for (const auto& [key, node] : keys_in_file_order(root)) {
    if (node->is_table()) continue;
    const std::string name(key->str());
    // video = "x.mp4" is [output]'s; video = 1 is a malformed [video] table (said later).
    const char* output_video = name == "video" && node->is_string() ? "[output]" : nullptr;
    for (const auto& [table, keys] : homes)
      if (output_video || std::find(keys.begin(), keys.end(), name) != keys.end())
        r.fail(key->source(), "key '" + name + "' is outside every table: it belongs under " +
                                  (output_video ? output_video : table) +
                                  " (a key goes below its table's header line)");
  }
}

}  // namespace

Timeline load_timeline(const std::vector<SceneInfo>& scenes, const std::string& path,
                       const ColorChecker* color, const ShaderLoader* shaders) {
  return parse_timeline(scenes, path, read_file(path), color, shaders);
}

Timeline parse_timeline(const std::vector<SceneInfo>& scenes, const std::string& path,
                        const std::string& text, const ColorChecker* color,
                        const ShaderLoader* shaders) {
  if (std::optional<TextPosition> bad = find_invalid_utf8(text))
    throw InputError(path, bad->line, bad->column, "the file is not valid UTF-8");

  Timeline tl;
  tl.path = path;
  tl.sha256 = sha256_hex(text);

  toml::table root;
  try {
    root = toml::parse(std::string_view(text), std::string_view(path));
  } catch (const toml::parse_error& e) {
    const toml::source_position where = e.source().begin;
    throw InputError(path, int(where.line), int(where.column),
                     toml_error_message(std::string(e.description())));
  }

  std::ostringstream canonical;
  canonical << toml::toml_formatter{root};
  tl.parsed_sha256 = sha256_hex(canonical.str());

  TomlReader r(path);
  check_top_level_keys(r, root);
  r.check_keys(root, "",
               {"video", "output", "color", "time", "camera", "params", "shader", "channels"});
  const SceneInfo& scene = parse_video(r, root, scenes, shaders, tl);
  parse_output(r, root, scene, tl);
  parse_color(r, root, tl);
  parse_time(r, root, tl);
  parse_camera(r, root, scene, tl);
  parse_params(r, root, scene, tl);
  check_across_tables(r, root, tl, color);
  return tl;
}

}  // namespace sdfreel
