#include "io/manifest.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/bounded_read.h"
#include "io/frame_files.h"
#include "io/manifest_journal.h"

namespace sdfreel {

using nlohmann::json;

bool ManifestHeader::same_render_as(const ManifestHeader& o) const {
  return timeline_parsed_sha256 == o.timeline_parsed_sha256 && scene == o.scene &&
         backend == o.backend && versions == o.versions && width == o.width && height == o.height &&
         fps_num == o.fps_num && fps_den == o.fps_den && frame_count == o.frame_count &&
         samples == o.samples && adaptive == o.adaptive && quality == o.quality &&
         color_config == o.color_config && display == o.display && view == o.view;
}

json manifest_frame_json(const ManifestFrame& f) {
  return {{"index", f.index},
          {"video_time", f.video_time},
          {"scene_time", f.scene_time},
          {"linear_md5", f.linear_hash},
          {"display_md5", f.display_md5},
          {"render_seconds", f.render_seconds},
          {"sdf_evals_per_pixel", f.sdf_evals_per_pixel}};
}

namespace {

// An integer field, exactly and in lo..hi: a number too big for 64 bits parses as a double, and
// converting that to an integer is undefined (found by fuzz_manifest); a 64-bit value narrowed
// to int would wrap (an index of 2^40 to frame 0).
int int_field(const json& v, const std::string& name, int64_t lo, int64_t hi) {
  if (!v.is_number_integer())
    throw std::runtime_error("malformed manifest: " + name + " is not an integer");
  const bool above =
      v.is_number_unsigned() ? v.get<uint64_t>() > uint64_t(hi) : v.get<int64_t>() > hi;
  if (above || (!v.is_number_unsigned() && v.get<int64_t>() < lo))
    throw std::runtime_error("malformed manifest: " + name + " " + v.dump() + " is outside " +
                             std::to_string(lo) + ".." + std::to_string(hi));
  return int(v.get<int64_t>());
}

constexpr int64_t kIntMax = std::numeric_limits<int>::max();

// "NUM/DEN", both whole numbers that fit 64 bits (sscanf's %ld is undefined past them).
bool parse_fps(const std::string& s, int64_t& num, int64_t& den) {
  const char* end = s.data() + s.size();
  const auto n = std::from_chars(s.data(), end, num);
  if (n.ec != std::errc() || n.ptr == end || *n.ptr != '/') return false;
  const auto d = std::from_chars(n.ptr + 1, end, den);
  return d.ec == std::errc() && d.ptr == end;
}

}  // namespace

ManifestFrame manifest_frame_from_json(const json& f, int frame_count) {
  ManifestFrame fr;
  fr.index = int_field(f.at("index"), "frame index", 0, int64_t(frame_count) - 1);
  fr.video_time = f.at("video_time");
  fr.scene_time = f.at("scene_time");
  fr.linear_hash = f.at("linear_md5");
  fr.display_md5 = f.at("display_md5");
  fr.render_seconds = f.at("render_seconds");
  fr.sdf_evals_per_pixel = f.value("sdf_evals_per_pixel", 0.0);
  return fr;
}

std::string manifest_to_json(const Manifest& m) {
  const ManifestHeader& h = m.header;
  json j;
  j["format"] = "sdfreel-manifest-1";
  j["timeline"] = {{"path", h.timeline_path},
                   {"sha256", h.timeline_sha256},
                   {"parsed_sha256", h.timeline_parsed_sha256}};
  j["scene"] = h.scene;
  j["backend"] = h.backend;
  j["versions"] = h.versions;
  j["resolution"] = {h.width, h.height};
  j["fps"] = std::to_string(h.fps_num) + "/" + std::to_string(h.fps_den);
  j["frame_count"] = h.frame_count;
  j["samples"] = h.samples;
  if (!h.adaptive.empty()) j["adaptive"] = h.adaptive;
  j["quality"] = h.quality;
  j["color"] = {{"config", h.color_config}, {"display", h.display}, {"view", h.view}};
  j["codec"] = h.codec;
  j["video"] = h.video;
  j["frame_files"] = h.frame_files;
  for (const auto& [key, value] : h.frame_options) {
    const bool number =
        !value.empty() && value.find_first_not_of("0123456789") == std::string::npos;
    j["frame_options"][key] = number ? json(std::stoi(value)) : json(value);
  }
  if (!h.audio_path.empty())
    j["audio"] = {{"path", h.audio_path},
                  {"sha256", h.audio_sha256},
                  {"offset", h.audio_offset},
                  {"fade", h.audio_fade}};
  if (!m.frames.empty()) j["frame_range"] = {m.frames.begin()->first, m.frames.rbegin()->first};
  json frames = json::array();
  for (const auto& [i, f] : m.frames) frames.push_back(manifest_frame_json(f));
  j["frames"] = frames;
  return j.dump(2) + "\n";
}

Manifest manifest_from_json(const std::string& text) {
  Manifest m;
  try {
    const json j = json::parse(text);
    ManifestHeader& h = m.header;
    h.timeline_path = j.at("timeline").at("path");
    h.timeline_sha256 = j.at("timeline").at("sha256");
    // Older manifests lack it: their renders count as other settings (rendered again).
    h.timeline_parsed_sha256 = j.at("timeline").value("parsed_sha256", "");
    h.scene = j.at("scene");
    h.backend = j.at("backend");
    h.versions = j.at("versions").get<std::map<std::string, std::string>>();
    h.width = int_field(j.at("resolution").at(0), "width", 1, kIntMax);
    h.height = int_field(j.at("resolution").at(1), "height", 1, kIntMax);
    const std::string fps = j.at("fps");
    if (!parse_fps(fps, h.fps_num, h.fps_den))
      throw std::runtime_error("malformed manifest: bad fps '" + fps + "'");
    h.frame_count = int_field(j.at("frame_count"), "frame_count", 0, kIntMax);
    h.samples = int_field(j.at("samples"), "samples", 1, kIntMax);
    h.adaptive = j.value("adaptive", "");
    h.quality = j.at("quality");
    h.color_config = j.at("color").at("config");
    h.display = j.at("color").at("display");
    h.view = j.at("color").at("view");
    h.codec = j.value("codec", "h264");
    h.video = j.value("video", "");
    h.frame_files = j.at("frame_files").get<std::vector<std::string>>();
    if (j.contains("frame_options"))
      for (const auto& [key, value] : j.at("frame_options").items())
        h.frame_options[key] =
            value.is_string()
                ? value.get<std::string>()
                : std::to_string(int_field(value, "frame_options." + key, 0, kIntMax));
    if (j.contains("audio")) {
      const json& a = j.at("audio");
      h.audio_path = a.at("path");
      h.audio_sha256 = a.at("sha256");
      h.audio_offset = a.at("offset").get<double>();
      h.audio_fade = a.at("fade").get<double>();
    }
    for (const json& f : j.at("frames")) {
      const ManifestFrame fr = manifest_frame_from_json(f, h.frame_count);
      m.frames[fr.index] = fr;
    }
  } catch (const json::exception& e) {
    // Drop the library's "[json.exception.parse_error.101] " tag: users read what is wrong.
    const std::string what = e.what();
    const size_t tag_end = what.find("] ");
    throw std::runtime_error("malformed manifest: " +
                             (tag_end == std::string::npos ? what : what.substr(tag_end + 2)));
  }
  return m;
}

std::optional<Manifest> read_manifest_json(const std::string& path) {
  const std::optional<std::string> text = read_regular_file(path, kMaxManifestBytes);
  if (!text) return std::nullopt;
  return manifest_from_json(*text);
}

std::optional<Manifest> read_manifest(const std::string& path) {
  std::optional<Manifest> m = read_manifest_json(path);
  if (!m) return m;
  // Frames finished since the last consolidation (or by a killed render) are in the journal.
  const std::string dir = std::filesystem::path(path).parent_path().string();
  merge_journal(dir.empty() ? "." : dir, render_key(m->header), *m);
  return m;
}

// FFmpeg's framemd5 muxer output, data lines "%d, %10lld, %10lld, %8lld, %8d, %s".
std::string framemd5_text(const Manifest& m) {
  const ManifestHeader& h = m.header;
  std::string out =
      "#format: frame checksums\n#version: 2\n#hash: MD5\n#tb 0: " + std::to_string(h.fps_den) +
      "/" + std::to_string(h.fps_num) +
      "\n#media_type 0: video\n#codec_id 0: rawvideo\n#dimensions 0: " + std::to_string(h.width) +
      "x" + std::to_string(h.height) +
      "\n#sar 0: 1/1\n#stream#, dts,        pts, duration,     size, hash\n";
  const long long size = 6LL * h.width * h.height;
  char line[256];
  for (const auto& [i, f] : m.frames) {
    std::snprintf(line, sizeof line, "%d, %10lld, %10lld, %8lld, %8lld, %s\n", 0, (long long)i,
                  (long long)i, 1LL, size, f.display_md5.c_str());
    out += line;
  }
  return out;
}

namespace {

// flock() on a side file: released when the descriptor closes, even if the process is killed.
class DirLock {
 public:
  explicit DirLock(const std::string& dir) {
    fd_ = ::open((dir + "/.manifest.lock").c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error("cannot open lock file in " + dir);
    ::flock(fd_, LOCK_EX);
  }
  ~DirLock() { ::close(fd_); }

 private:
  int fd_;
};

// manifest.json if it belongs to this render, else nothing; `damaged` says why it was not used,
// `foreign` receives it when it belongs to other settings.
std::optional<Manifest> load_own(const std::string& dir, const ManifestHeader& header,
                                 std::string* damaged, std::optional<Manifest>* foreign) {
  std::optional<Manifest> m;
  try {
    m = read_manifest_json(dir + "/manifest.json");
  } catch (const std::exception& e) {
    if (damaged) *damaged = e.what();  // a damaged manifest is replaced, never trusted
    return std::nullopt;
  }
  if (m && !m->header.same_render_as(header)) {
    if (foreign) *foreign = std::move(m);
    return std::nullopt;
  }
  return m;
}

void write_both(const std::string& dir, const Manifest& m) {
  write_text_atomic(dir + "/manifest.json", manifest_to_json(m));
  write_text_atomic(dir + "/frames.framemd5", framemd5_text(m));
}

}  // namespace

void record_frame(const std::string& dir, const ManifestHeader& header,
                  const ManifestFrame& frame) {
  DirLock lock(dir);
  append_journal(dir, render_key(header), frame);
}

Manifest consolidate_manifest(const std::string& dir, const ManifestHeader& header,
                              std::string* damaged,
                              const std::function<void(const Manifest*)>& on_foreign) {
  DirLock lock(dir);
  std::optional<Manifest> foreign;
  std::optional<Manifest> own = load_own(dir, header, damaged, &foreign);
  // May throw: refuse to replace a live render's manifest.
  if (on_foreign) on_foreign(foreign ? &*foreign : nullptr);
  Manifest m = own ? *own : Manifest{header, {}};
  m.header = header;
  merge_journal(dir, render_key(header), m);
  write_both(dir, m);
  clear_journal(dir);  // after the rewrite: a kill in between leaves duplicates, never losses
  return m;
}

}  // namespace sdfreel
