// `sdfreel verify TIMELINE --manifest FILE`: re-render and compare every frame's hashes.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "cli/commands_impl.h"
#include "cli/output_folder.h"
#include "cli/verify_tolerance.h"
#include "io/display_compare.h"
#include "io/frame_files.h"
#include "io/hash_reference.h"
#include "io/manifest_differences.h"
#include "io/manifest_journal.h"
#include "pipeline/shader_checkpoints.h"

namespace sdfreel {

namespace {

struct VerifyOptions {
  RenderOptions render;
  std::string manifest;
  std::string tolerance;   // "" (bit for bit) or "filament"
  bool fail_fast = false;  // stop at the first differing frame
};

// With a tolerance the renderer may differ (that is its purpose): only the settings must agree.
bool renderer_line(const std::string& line) {
  return line.rfind("backend:", 0) == 0 || line.rfind("versions.", 0) == 0;
}

// A framemd5 holds no settings; its frame size at least tells another resolution or pixel format.
bool same_frame_size(const HashReference& ref, const Timeline& tl, const std::string& path) {
  const int64_t bytes = 6LL * tl.width * tl.height;
  for (const auto& [i, want] : ref.frames) {
    if (want.size < 0 || want.size == bytes) continue;
    std::fprintf(
        stderr,
        "sdfreel: verify failed: %s lists frame %d with %lld bytes, this timeline's frames "
        "have %lld (rgb48le, %dx%d): made at another resolution or pixel format\n",
        path.c_str(), i, (long long)want.size, (long long)bytes, tl.width, tl.height);
    return false;
  }
  return true;
}

int run_verify(const VerifyOptions& o) {
  HashReference ref;
  try {
    ref = read_hash_reference(o.manifest);
  } catch (const HashReferenceError& e) {
    throw UsageError(e.what());
  }
  Timeline tl = load_with_overrides(o.render);
  FramePipeline pipe(tl, timeline_backend(tl, o.render));
  const ManifestHeader header = manifest_header(tl, pipe.backend());
  if (ref.header && !header.same_render_as(*ref.header)) {
    std::vector<std::string> lines = header_differences(header, *ref.header);
    if (!o.tolerance.empty())
      lines.erase(std::remove_if(lines.begin(), lines.end(), renderer_line), lines.end());
    if (!lines.empty()) {
      std::fprintf(stderr, "sdfreel: verify failed: %s was made with other settings:\n",
                   o.manifest.c_str());
      for (const std::string& line : lines) std::fprintf(stderr, "  %s\n", line.c_str());
      return 1;
    }
  }
  if (!same_frame_size(ref, tl, o.manifest)) return 1;
  const std::string dir = std::filesystem::path(o.manifest).parent_path().string();
  const std::string out_dir = o.render.out.empty() ? (dir.empty() ? "." : dir) : o.render.out;
  // The reference's checkpoints of a shader's buffers, read only: frames of the same settings.
  use_shader_checkpoints(pipe, dir.empty() ? "." : dir, render_key(header), false);
  if (!o.tolerance.empty())
    return verify_within_tolerance(pipe, selected_frames(tl, o.render), dir.empty() ? "." : dir,
                                   out_dir);
  int checked = 0;
  std::vector<int> differing;
  for (int i : selected_frames(tl, o.render)) {
    auto it = ref.frames.find(i);
    if (it == ref.frames.end()) continue;
    RenderedFrame f = pipe.render(i);
    ++checked;
    const ReferenceFrame& want = it->second;
    const bool linear_ok = want.linear_hash.empty() || f.linear_hash == want.linear_hash;
    if (linear_ok && f.display_md5 == want.display_md5) {
      std::fprintf(stderr, "frame %05d ok\n", i);
      continue;
    }
    differing.push_back(i);
    std::filesystem::create_directories(out_dir);
    char name[64];
    std::snprintf(name, sizeof name, "/verify-%05d-", i);
    const std::string reference = frame_path(dir.empty() ? "." : dir, i, "png");
    std::string written;
    if (std::filesystem::exists(reference)) {
      written = out_dir + name + "diff.png";
      write_png16_atomic(written, difference_image(f.display, read_png16(reference), 16.0));
    } else {
      written = out_dir + name + "rendered.png";
      write_png16_atomic(written, f.display);
    }
    std::fprintf(stderr,
                 "sdfreel: verify failed: frame %d differs (display md5 %s, %s %s; linear %s, "
                 "%s %s); wrote %s\n",
                 i, f.display_md5.c_str(), ref.kind.c_str(), want.display_md5.c_str(),
                 f.linear_hash.c_str(), ref.kind.c_str(),
                 want.linear_hash.empty() ? "-" : want.linear_hash.c_str(), written.c_str());
    if (o.fail_fast) return 1;
  }
  if (checked == 0) {
    std::fprintf(stderr, "sdfreel: verify failed: %s lists none of the selected frames\n",
                 o.manifest.c_str());
    return 1;
  }
  if (!differing.empty()) {
    std::string list;
    for (size_t k = 0; k < differing.size(); ++k)
      list += (k ? ", " : "") + std::to_string(differing[k]);
    std::fprintf(stderr, "sdfreel: verify failed: %zu of %d frames differ: %s\n", differing.size(),
                 checked, list.c_str());
    return 1;
  }
  std::fprintf(stderr, "verified %d frames: all hashes match\n", checked);
  return 0;
}

}  // namespace

void add_verify_command(CLI::App& app, int& status) {
  auto o = std::make_shared<VerifyOptions>();
  CLI::App* cmd = app.add_subcommand("verify", "re-render and compare every frame with a manifest");
  add_frame_options(cmd, o->render);  // no --no-video or --resume: verify writes no render
  // verify makes no render folder: its --out is where the images of differing frames go.
  cmd->get_option("--out")->description(
      "folder for the diff and rendered images of frames that differ (default: the manifest's "
      "folder)");
  cmd->add_option(
         "--manifest", o->manifest,
         "manifest.json or framemd5 (sdfreel's or ffmpeg -f framemd5) of an earlier render")
      ->required();
  cmd->add_option("--tolerance", o->tolerance,
                  "filament: hold frames to the golden PNGs beside the manifest by Filament's "
                  "rule (for another renderer, e.g. a GPU) instead of by hash")
      ->check(CLI::IsMember({"filament"}));
  cmd->add_flag("--fail-fast", o->fail_fast, "stop at the first frame that differs");
  cmd->callback([o, &status] { status = run_verify(*o); });
}

}  // namespace sdfreel
