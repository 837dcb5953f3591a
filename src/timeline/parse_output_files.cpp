// [output] frames: "exr" and "png" have writers of their own; any other name is a file extension
// OpenImageIO writes, checked against its writers when the command starts
// (validate_frame_formats), since this library does not link OpenImageIO. [output] audio: the
// soundtrack, opened when the command starts as well.
#include <algorithm>
#include <filesystem>

#include "timeline/sections.h"

namespace sdfreel {
namespace {

void add_frame_format(const TomlReader& r, const toml::node& n, const std::string& name,
                      Timeline& tl) {
  const std::string f = r.string(n, name);
  if (f == "exr" || f == "png") {
    (f == "exr" ? tl.write_exr : tl.write_png) = true;
    return;
  }
  const bool plain = !f.empty() && f.size() <= 8 && std::all_of(f.begin(), f.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
  });
  if (!plain)
    r.fail(n, name + " = \"" + f +
                  "\": name a frame format by its file extension in lower case, without the dot "
                  "(exr, png, tiff, tif, dpx, jpg, ...)");
  for (const Timeline::OtherFrames& o : tl.other_frames)
    if (o.ext == f) return;
  const toml::source_position at = n.source().begin;
  tl.other_frames.push_back({f, int(at.line), int(at.column)});
}

int one_of(const TomlReader& r, const toml::node& n, const std::string& name,
           const std::vector<int>& allowed) {
  const int64_t v = r.integer(n, name);
  if (std::find(allowed.begin(), allowed.end(), v) != allowed.end()) return int(v);
  std::vector<std::string> names;
  names.reserve(allowed.size());  // no growth: GCC 14 warns (falsely) of one in push_back
  for (int a : allowed) names.push_back(std::to_string(a));
  r.fail(n, name + " = " + std::to_string(v) + ": use " + join(names, " or "));
}

}  // namespace

void parse_soundtrack(const TomlReader& r, const toml::table& output, Timeline& tl) {
  const toml::node* n = output.get("audio");
  for (const char* key : {"audio_offset", "audio_fade"})
    if (!n && output.contains(key))
      r.fail(*output.get(key), std::string("output.") + key + " needs output.audio, the file");
  if (!n) return;
  const std::string given = r.string(*n, "output.audio");
  if (given.empty()) r.fail(*n, "output.audio is empty: name an audio file (.flac, .wav, ...)");
  namespace fs = std::filesystem;
  tl.audio.path = fs::path(given).is_absolute()
                      ? given
                      : (fs::path(r.file()).parent_path() / given).lexically_normal().string();
  const toml::source_position at = n->source().begin;
  tl.audio.line = int(at.line);
  tl.audio.column = int(at.column);
  if (const toml::node* o = output.get("audio_offset")) {
    tl.audio.offset = r.number(*o, "output.audio_offset");
    if (tl.audio.offset < 0) r.fail(*o, "output.audio_offset must be >= 0 seconds");
  }
  if (const toml::node* f = output.get("audio_fade")) {
    tl.audio.fade = r.number(*f, "output.audio_fade");
    if (tl.audio.fade < 0) r.fail(*f, "output.audio_fade must be >= 0 seconds");
  }
}

void parse_frame_files(const TomlReader& r, const toml::table& output, Timeline& tl) {
  if (const toml::node* n = output.get("frames")) {
    const toml::array& formats = r.array(*n, "output.frames");
    tl.write_exr = tl.write_png = false;
    for (size_t i = 0; i < formats.size(); ++i)
      add_frame_format(r, *formats.get(i), "output.frames[" + std::to_string(i) + "]", tl);
  }
  FrameFileOptions& options = tl.frame_options;
  if (const toml::node* n = output.get("tiff_bits"))
    options.tiff_bits = one_of(r, *n, "output.tiff_bits", {8, 16, 32});
  if (const toml::node* n = output.get("dpx_bits"))
    options.dpx_bits = one_of(r, *n, "output.dpx_bits", {8, 10, 12, 16});
  if (const toml::node* n = output.get("jpeg_quality"))
    options.jpeg_quality = int(r.integer_in(*n, "output.jpeg_quality", 1, 100));
  if (const toml::node* n = output.get("exr_compression"))
    options.exr_compression = r.choice(*n, "output.exr_compression", exr_compression_names());
  if (const toml::node* n = output.get("exr_bits"))
    options.exr_bits = one_of(r, *n, "output.exr_bits", {16, 32});
}

}  // namespace sdfreel
