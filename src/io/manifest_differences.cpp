#include "io/manifest_differences.h"

#include <set>

namespace sdfreel {

namespace {

struct Differences {
  std::vector<std::string> lines;
  void check(const std::string& field, const std::string& here, const std::string& there) {
    if (here == there) return;
    const auto shown = [](const std::string& v) { return v.empty() ? "(none)" : v; };
    lines.push_back(field + ": " + shown(here) + " here, " + shown(there) + " in the manifest");
  }
  void check(const std::string& field, int64_t here, int64_t there) {
    check(field, std::to_string(here), std::to_string(there));
  }
};

}  // namespace

std::vector<std::string> header_differences(const ManifestHeader& a, const ManifestHeader& b) {
  Differences d;
  d.check("timeline (parsed, sha256)", a.timeline_parsed_sha256, b.timeline_parsed_sha256);
  d.check("scene", a.scene, b.scene);
  d.check("backend", a.backend, b.backend);
  std::set<std::string> keys;
  for (const auto& [k, v] : a.versions) keys.insert(k);
  for (const auto& [k, v] : b.versions) keys.insert(k);
  for (const std::string& k : keys) {
    const auto here = a.versions.find(k), there = b.versions.find(k);
    d.check("versions." + k, here == a.versions.end() ? "" : here->second,
            there == b.versions.end() ? "" : there->second);
  }
  d.check("resolution", std::to_string(a.width) + "x" + std::to_string(a.height),
          std::to_string(b.width) + "x" + std::to_string(b.height));
  d.check("fps", std::to_string(a.fps_num) + "/" + std::to_string(a.fps_den),
          std::to_string(b.fps_num) + "/" + std::to_string(b.fps_den));
  d.check("frame_count", a.frame_count, b.frame_count);
  d.check("samples", a.samples, b.samples);
  d.check("adaptive", a.adaptive, b.adaptive);
  d.check("quality", a.quality, b.quality);
  d.check("color_config", a.color_config, b.color_config);
  d.check("display", a.display, b.display);
  d.check("view", a.view, b.view);
  return d.lines;
}

}  // namespace sdfreel
