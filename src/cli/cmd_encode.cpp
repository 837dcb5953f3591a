// `sdfreel encode DIR -o VIDEO`: encode frames already on disk (e.g. rendered in shards), each
// checked against DIR's manifest first.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "cli/commands_impl.h"
#include "cli/manifest_input.h"
#include "cli/output_folder.h"
#include "cli/soundtrack.h"
#include "cli/time_overrides.h"
#include "cli/video_choice.h"
#include "io/video_codecs.h"
#include "io/video_encoder.h"
#include "timeline/rules.h"
#include "timeline/video_codec_rules.h"

namespace sdfreel {

namespace {

struct EncodeOptions {
  std::string dir, output, codec, fps;
  int crf = 18;
};

int run_encode(const EncodeOptions& o) {
  const std::optional<Manifest> manifest = read_manifest_argument(o.dir + "/manifest.json");
  const ManifestHeader& h = manifest->header;
  const std::string codec = o.codec.empty() ? codec_of_output(o.output, h.codec, "-o") : o.codec;
  const VideoCodecRule* rule = find_video_codec_rule(codec);
  if (!rule) throw UsageError("unknown codec '" + codec + "' (" + known_video_codecs() + ")");
  if (std::string missing = missing_video_encoder(codec); !missing.empty())
    throw UsageError(missing);
  // The container must hold the codec: refused here, before a temporary video is created.
  const std::string name = std::filesystem::path(o.output).filename().string();
  if (std::string problem = check_video_name(name, codec); !problem.empty())
    throw UsageError("-o " + o.output + ": " + problem.substr(problem.find(':') + 2));
  if (rule->even_size && (h.width % 2 || h.height % 2))
    throw UsageError(codec + " (" + rule->pix_fmt +
                     ") needs an even width and height; the frames are " + std::to_string(h.width) +
                     "x" + std::to_string(h.height));
  Rational fps{h.fps_num, h.fps_den};
  if (!o.fps.empty()) fps = parse_fps_option(o.fps);
  // Every frame of the timeline must be there: a video with a hole is not the timeline's video.
  for (int i = 0; i < h.frame_count; ++i)
    if (!manifest->frames.count(i)) {
      std::fprintf(stderr, "sdfreel: error: frame %d of %d is not in %s/manifest.json\n", i,
                   h.frame_count, o.dir.c_str());
      return 1;
    }
  DisplayTransform display(h.color_config, h.display, h.view);
  VideoEncoder encoder(VideoSettings{o.output, codec, h.width, h.height, fps, o.crf,
                                     encode_soundtrack_of(h, fps, o.output)});
  for (int i = 0; i < h.frame_count; ++i) {
    std::string why;
    auto shown = load_checked_frame(o.dir, h, manifest->frames.at(i), display, &why);
    if (!shown) {
      std::fprintf(stderr, "sdfreel: error: frame %d: %s\n", i, why.c_str());
      return 1;
    }
    encoder.add_frame(*shown);
  }
  encoder.finish();
  std::fprintf(stderr, "wrote %s (%d frames, %s)\n", o.output.c_str(), h.frame_count,
               codec.c_str());
  return 0;
}

}  // namespace

void add_encode_command(CLI::App& app, int& status) {
  auto o = std::make_shared<EncodeOptions>();
  CLI::App* cmd = app.add_subcommand("encode", "encode the frames of a render folder into a video");
  cmd->add_option("DIR", o->dir, "render output folder (with manifest.json)")->required();
  cmd->add_option("-o,--output", o->output, "video file to write")->required();
  cmd->add_option("--codec", o->codec,
                  "h264 | h264-10bit | hevc | hevc-10bit | vp9 | av1 | ffv1 | prores | webp | gif "
                  "(default: the container's: .mp4 h264, .mkv ffv1, .mov prores, .webm vp9, "
                  ".webp webp, .gif gif; a container that also fits the render's codec asks)");
  cmd->add_option("--fps", o->fps, "frame rate, integer or N/D (default: the timeline's)");
  cmd->add_option("--crf", o->crf,
                  "quality of the lossy codecs (h264, hevc, vp9, av1, their 10-bit kinds, webp), "
                  "0..51, lower is better")
      ->check(CLI::Range(0, 51));
  cmd->callback([o, &status] { status = run_encode(*o); });
}

}  // namespace sdfreel
