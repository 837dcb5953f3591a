// Rules for [output] names, checked with the rest of the timeline so that a render never creates
// its folder, lock and manifest for a video it cannot write.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "timeline/rules.h"

namespace sdfreel {
namespace {

struct Container {
  const char* extension;
  const char* usual;  // the codec the extension stands for when none is named
  // Our rule, the same on every FFmpeg: pairings libav's muxer accepts (tests/cli checks each
  // against the installed libav; a newer one may accept more).
  const char* codecs[8];
};

constexpr Container kContainers[] = {
    {".mp4", "h264", {"h264", "h264-10bit", "hevc", "hevc-10bit", "av1"}},
    {".mkv", "ffv1", {"h264", "h264-10bit", "hevc", "hevc-10bit", "vp9", "av1", "ffv1", "prores"}},
    {".mov", "prores", {"h264", "h264-10bit", "hevc", "hevc-10bit", "prores"}},
    {".webm", "vp9", {"vp9", "av1"}},
    {".webp", "webp", {"webp"}},
    {".gif", "gif", {"gif"}},
};

}  // namespace

std::string lower_extension(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  const size_t dot = name.rfind('.');
  if (dot == std::string::npos || dot == 0) return "";
  std::string ext = name.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

std::string check_path_text(const std::string& key, const std::string& text) {
  for (unsigned char c : text)
    if (c < 0x20 || c == 0x7f)
      return key + " contains a control character (code " + std::to_string(int(c)) +
             "); file names cannot hold it";
  return "";
}

std::string usual_codec(const std::string& name) {
  const std::string ext = lower_extension(name);
  for (const Container& c : kContainers)
    if (ext == c.extension) return c.usual;
  return "";
}

bool container_holds(const std::string& name, const std::string& codec) {
  const std::string ext = lower_extension(name);
  for (const Container& c : kContainers)
    if (ext == c.extension)
      for (const char* fits : c.codecs)
        if (fits && codec == fits) return true;
  return false;
}

std::string check_video_name(const std::string& name, const std::string& codec) {
  if (name.empty()) return "";
  if (std::string problem = check_path_text("output.video", name); !problem.empty()) return problem;
  if (name.find('/') != std::string::npos || name == "." || name == "..")
    return "output.video '" + name + "' must be a file name; it is written into output.dir";
  const std::string ext = lower_extension(name);
  for (const Container& c : kContainers) {
    if (ext != c.extension) continue;
    for (const char* fits : c.codecs)
      if (fits && codec == fits) return "";
    std::string fitting;
    for (const Container& other : kContainers)
      for (const char* fits : other.codecs)
        if (fits && codec == fits)
          fitting += std::string(fitting.empty() ? "" : ", ") + other.extension;
    return "output.video '" + name + "': a " + ext + " file cannot hold codec " + codec + " (use " +
           fitting + ")";
  }
  return "output.video '" + name + "': unknown container '" + ext +
         "' (use .mp4, .mkv, .mov, .webm, .webp or .gif)";
}

}  // namespace sdfreel
