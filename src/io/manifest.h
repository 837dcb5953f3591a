#pragma once
// manifest.json (docs/cli.md): what was rendered, with which settings and libraries, and per-frame
// hashes and times. Also writes frames.framemd5 from it. During a render, finished frames are
// appended to manifest.journal (O(1) a frame, see manifest_journal.h); manifest.json and
// frames.framemd5 are rewritten atomically from both when a render starts and ends, under a file
// lock, so concurrent shards in one folder merge instead of clobbering.
#include <functional>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

namespace sdfreel {

struct ManifestFrame {
  int index = 0;
  double video_time = 0.0;
  double scene_time = 0.0;
  std::string linear_hash;  // MD5 of half RGBA (what the EXR stores)
  std::string display_md5;  // MD5 of rgb48le display pixels (what framemd5 lists)
  double render_seconds = 0.0;
  double sdf_evals_per_pixel = 0.0;
};

// Everything that must agree for two renders' frames to be interchangeable (resume, shards).
struct ManifestHeader {
  std::string timeline_sha256;         // of the file's bytes (reported)
  std::string timeline_parsed_sha256;  // of the parsed timeline (compared): Timeline::parsed_sha256
  std::string timeline_path;
  std::string scene;
  std::string backend;
  std::map<std::string, std::string> versions;
  int width = 0, height = 0;
  int64_t fps_num = 30, fps_den = 1;
  int frame_count = 0;  // frames in the whole timeline
  int samples = 1;
  std::string adaptive;  // adaptive sampling's settings ("" = fixed `samples`)
  std::string quality;
  std::string color_config, display, view;
  std::string codec;                     // of the timeline, used by `encode` as the default
  std::string video;                     // file name the timeline asks for ("" none)
  std::vector<std::string> frame_files;  // extensions: "exr", "png", "tif", ...
  // The [output] options that shape those files ("tiff_bits": 32), absent in the JSON when there
  // are none (io/frame_formats.h); numbers are written as JSON numbers.
  std::map<std::string, std::string> frame_options;
  // The soundtrack ([output] audio) `encode` puts under the video; "" none. Not compared by
  // same_render_as: the audio changes no frame.
  std::string audio_path, audio_sha256;
  double audio_offset = 0.0, audio_fade = 0.0;
  bool same_render_as(
      const ManifestHeader& o) const;  // all fields but timeline_path/versions order
};

struct Manifest {
  ManifestHeader header;
  std::map<int, ManifestFrame> frames;  // by frame index
};

std::string manifest_to_json(const Manifest& m);
Manifest manifest_from_json(const std::string& text);  // throws std::runtime_error
nlohmann::json manifest_frame_json(const ManifestFrame& f);
// Throws for a missing field or an index outside 0..frame_count-1.
ManifestFrame manifest_frame_from_json(const nlohmann::json& f, int frame_count);
// manifest.json alone; nullopt if missing.
std::optional<Manifest> read_manifest_json(const std::string& path);
// manifest.json plus the frames its folder's journal adds; nullopt if manifest.json is missing.
std::optional<Manifest> read_manifest(const std::string& path);
std::string framemd5_text(const Manifest& m);

// Locks DIR/.manifest.lock and appends `frame` to the journal: O(1), whatever the frame count.
void record_frame(const std::string& dir, const ManifestHeader& header, const ManifestFrame& frame);
// Locks DIR/.manifest.lock, merges DIR/manifest.json (when it belongs to this render) with the
// journal, rewrites manifest.json and frames.framemd5, empties the journal and returns the result.
// `damaged` receives why an unreadable manifest.json was set aside. `on_foreign` is called under
// the lock before anything is written, with the manifest of other settings the folder holds
// (nullptr when it holds none); it may throw to refuse.
Manifest consolidate_manifest(const std::string& dir, const ManifestHeader& header,
                              std::string* damaged = nullptr,
                              const std::function<void(const Manifest*)>& on_foreign = nullptr);

}  // namespace sdfreel
