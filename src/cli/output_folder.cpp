#include "cli/output_folder.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "cli/soundtrack.h"
#include "io/frame_files.h"
#include "io/frame_formats.h"
#include "io/hashing.h"
#include "io/versions.h"
#include "pipeline/errors.h"

namespace sdfreel {

std::string frame_path(const std::string& dir, int index, const std::string& ext) {
  char name[32];
  std::snprintf(name, sizeof name, "%05d.", index);  // more digits only past 99999
  return dir + "/frames/" + name + ext;
}

ManifestHeader manifest_header(const Timeline& tl, Backend& backend) {
  ManifestHeader h;
  h.timeline_sha256 = tl.sha256;
  h.timeline_parsed_sha256 = tl.parsed_sha256;
  h.timeline_path = tl.path;
  h.scene = tl.scene;
  h.backend = backend.name();
  h.versions = io_library_versions();
  for (const auto& [k, v] : backend.versions()) h.versions[backend.name() + "." + k] = v;
  h.versions["sdfreel"] = SDFREEL_VERSION;
  h.width = tl.width;
  h.height = tl.height;
  h.fps_num = tl.fps.num;
  h.fps_den = tl.fps.den;
  h.frame_count = tl.frame_count();
  h.samples = tl.samples;
  if (tl.adaptive.enabled) h.adaptive = adaptive_text(tl.adaptive_at_size());
  h.quality = quality_name(tl.quality);
  h.color_config = tl.color_config;
  h.display = tl.display;
  h.view = tl.view;
  h.codec = tl.codec;
  h.video = tl.video;
  h.frame_files = timeline_frame_files(tl);
  h.frame_options = frame_option_values(h.frame_files, tl.frame_options);
  h.audio_path = tl.audio.path;
  h.audio_sha256 = soundtrack_sha256(tl);
  h.audio_offset = tl.audio.offset;
  h.audio_fade = tl.audio.fade;
  return h;
}

void check_output_folder(const std::string& dir) {
  std::error_code ec;
  for (std::filesystem::path p = std::filesystem::absolute(dir, ec); !p.empty();
       p = p.parent_path()) {
    const std::filesystem::file_status st = std::filesystem::status(p, ec);
    if (std::filesystem::is_directory(st)) return;  // the rest can be made inside it
    if (std::filesystem::exists(st))
      throw UsageError(
          "output folder " + dir + ": " + p.string() +
          " is a file, not a folder; choose another folder with --out or [output] dir");
    if (p == p.parent_path()) return;
  }
}

std::optional<ImageRGB16> load_checked_frame(const std::string& dir, const ManifestHeader& header,
                                             const ManifestFrame& entry,
                                             const DisplayTransform& display, std::string* why) {
  auto fail = [&](const std::string& msg) -> std::optional<ImageRGB16> {
    if (why) *why = msg;
    return std::nullopt;
  };
  const FrameFileOptions options = frame_options_from_values(header.frame_options);
  try {
    std::optional<ImageRGBA> linear;
    std::optional<ImageRGB16> shown;
    std::string linear_from, delivered;  // delivered: a file checked only to be there
    for (const std::string& ext : header.frame_files) {
      const std::string p = frame_path(dir, entry.index, ext);
      if (!std::filesystem::exists(p)) return fail(p + " is missing");
      const FrameFormat format = frame_format(ext, options);
      if (!format.exact) {
        delivered = p;
        continue;
      }
      FrameFilePixels got = read_frame_file(p, format);
      if (got.linear && linear_half_hash(*got.linear) != entry.linear_hash)
        return fail(p + " differs from the manifest");
      if (got.display && md5_rgb48le(*got.display) != entry.display_md5)
        return fail(p + " differs from the manifest");
      if (got.linear && !linear) {
        linear = std::move(got.linear);
        linear_from = p;
      }
      if (got.display && !shown) shown = std::move(got.display);
    }
    if (!shown && linear) {
      shown = display.apply(*linear);
      if (md5_rgb48le(*shown) != entry.display_md5)
        return fail(linear_from + " gives display pixels that differ from the manifest");
    }
    if (!shown && !delivered.empty())
      return fail(delivered +
                  " cannot be checked against the manifest (its format keeps fewer bits than "
                  "the hashed pixels): keep exr, png or 16-bit tiff frames beside it");
    if (!shown) return fail("the manifest lists no frame files");
    return shown;
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}

}  // namespace sdfreel
