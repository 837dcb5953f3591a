// [video], [output] and [color]: the timeline's fixed settings.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <numeric>

#include "timeline/rules.h"
#include "timeline/sections.h"
#include "timeline/suggest.h"
#include "timeline/video_codec_rules.h"

namespace sdfreel {
namespace {

// Bounds that keep frame * den exact in a double (video_time) and the frame count in an int.
constexpr int64_t kMaxFpsNumerator = 1000000000;
constexpr int64_t kMaxFpsDenominator = 1000000;
constexpr double kMaxFrames = 1e8;

const toml::table* section(const TomlReader& r, const toml::table& root, const char* name) {
  const toml::node* n = root.get(name);
  return n ? &r.table(*n, name) : nullptr;
}

bool parse_int(std::string_view s, int64_t& out) {
  if (s.empty()) return false;
  const char* end = s.data() + s.size();
  auto [p, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && p == end;
}

// fps: a positive integer, or a rational string "NUM/DEN" (or "NUM").
Rational parse_fps(const TomlReader& r, const toml::node& n) {
  const std::string name = "video.fps";
  Rational fps;
  if (const auto* i = n.as_integer()) {
    fps = {i->get(), 1};
  } else if (const auto* s = n.as_string()) {
    const std::string text(s->get());
    const size_t slash = text.find('/');
    fps.den = 1;
    const bool ok = slash == std::string::npos
                        ? parse_int(text, fps.num)
                        : parse_int(std::string_view(text).substr(0, slash), fps.num) &&
                              parse_int(std::string_view(text).substr(slash + 1), fps.den);
    if (!ok) r.fail(n, name + " \"" + text + "\" is not a rational number such as \"30000/1001\"");
    if (fps.den == 0) r.fail(n, name + " \"" + text + "\" divides by zero");
  } else {
    r.fail(n, name + " must be an integer or a rational string such as \"30000/1001\", not " +
                  type_name(n));
  }
  // Negative denominators are refused rather than flipped: the message stays simple and
  // negating INT64_MIN cannot overflow.
  if (fps.num <= 0 || fps.den < 0) r.fail(n, name + " must be > 0");
  const int64_t g = std::gcd(fps.num, fps.den);
  fps = {fps.num / g, fps.den / g};
  if (fps.num > kMaxFpsNumerator || fps.den > kMaxFpsDenominator)
    r.fail(n, name + " is too fine: numerator at most " + std::to_string(kMaxFpsNumerator) +
                  ", denominator at most " + std::to_string(kMaxFpsDenominator));
  return fps;
}

std::string timeline_stem(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

// [video] scene = NAME: one of the built-in scenes.
const SceneInfo& parse_scene_key(const TomlReader& r, const toml::table& root,
                                 const toml::table& video, const std::vector<SceneInfo>& scenes,
                                 Timeline& tl) {
  for (const char* table : {"shader", "channels"})
    if (const toml::node* n = root.get(table))
      r.fail(*n, std::string("[") + table +
                     "] belongs to a timeline of a user's shader ([video] shader = \"PATH\"), "
                     "not to a built-in scene's");
  const toml::node& scene_node = r.require(video, "scene", "[video]");
  tl.scene = r.string(scene_node, "video.scene");
  std::vector<std::string> names;
  for (const SceneInfo& s : scenes) {
    names.push_back(s.name);
    if (s.name == tl.scene) return s;
  }
  std::string hint = did_you_mean(tl.scene, names);
  r.fail(scene_node, "unknown scene '" + tl.scene + "'" +
                         (hint.empty() ? " (known scenes: " + join(names, ", ") + ")" : hint));
}

// [video] shader = PATH: a user's shader (docs/shaders.md), relative to the timeline's folder.
const SceneInfo& parse_shader_key(const TomlReader& r, const toml::table& root,
                                  const toml::table& video, const ShaderLoader* shaders,
                                  Timeline& tl) {
  const toml::node& n = *video.get("shader");
  if (video.contains("scene"))
    r.fail(*video.get("scene"), "[video] names either a scene or a shader, not both");
  const std::string given = r.string(n, "video.shader");
  if (given.empty()) r.fail(n, "video.shader is empty: name a shader folder, .glsl or .json file");
  if (!shaders) r.fail(n, "this command cannot render a user's shader");
  namespace fs = std::filesystem;
  tl.shader = fs::path(given).is_absolute()
                  ? given
                  : (fs::path(r.file()).parent_path() / given).lexically_normal().string();
  tl.scene = "shader:" + given;
  tl.shader_scene = shaders->load(r, root, tl.shader, tl.scene);
  return *tl.shader_scene;
}

}  // namespace

const SceneInfo& parse_video(const TomlReader& r, const toml::table& root,
                             const std::vector<SceneInfo>& scenes, const ShaderLoader* shaders,
                             Timeline& tl) {
  const toml::table* video = section(r, root, "video");
  if (!video)
    r.fail(toml::source_region{},
           "missing table [video] (its 'scene' or 'shader' key is required)");
  r.check_keys(*video, "[video]",
               {"scene", "shader", "fps", "duration", "resolution", "samples", "adaptive",
                "quality", "seed"});
  const SceneInfo* scene = video->contains("shader")
                               ? &parse_shader_key(r, root, *video, shaders, tl)
                               : &parse_scene_key(r, root, *video, scenes, tl);

  const toml::node* fps_node = video->get("fps");
  if (fps_node) tl.fps = parse_fps(r, *fps_node);
  const toml::node* duration_node = video->get("duration");
  if (duration_node) {
    tl.duration = r.number(*duration_node, "video.duration");
    if (!(tl.duration > 0.0))
      r.fail(*duration_node, "video.duration must be > 0, got " + format_number(tl.duration));
  }
  if (tl.duration * tl.fps.value() > kMaxFrames) {
    const toml::node* culprit = duration_node ? duration_node : fps_node;
    r.fail(culprit ? culprit->source() : video->source(),
           "video.duration * fps is more than " + format_number(kMaxFrames) + " frames");
  }

  if (const toml::node* n = video->get("resolution")) {
    const std::string name = "video.resolution";
    const toml::array* a = n->as_array();
    if (!a || a->size() != 2 || !a->get(0)->is_integer() || !a->get(1)->is_integer())
      r.fail(*n, name + " must be an array of two integers [width, height]");
    const int64_t w = r.integer(*a->get(0), name), h = r.integer(*a->get(1), name);
    if (std::string problem = check_resolution(w, h); !problem.empty()) r.fail(*n, problem);
    tl.width = int(w);
    tl.height = int(h);
    tl.resolution_line = int(n->source().begin.line);
    tl.resolution_column = int(n->source().begin.column);
  }
  if (tl.shader_scene) tl.samples = 1;  // Shadertoy's one sample a pixel, unless asked
  if (const toml::node* n = video->get("samples")) {
    const int64_t s = r.integer(*n, "video.samples");
    if (std::string problem = check_samples(s); !problem.empty()) r.fail(*n, problem);
    tl.samples = int(s);
  }
  if (const toml::node* n = video->get("quality")) {
    const std::vector<std::string> names = {"draft", "final", "reference"};
    std::optional<Quality> q = parse_quality(r.choice(*n, "video.quality", names));
    if (!q) r.fail(*n, "video.quality is not known to this build");
    tl.quality = *q;
  }
  if (const toml::node* n = video->get("seed"))
    tl.seed = uint64_t(r.integer_in(*n, "video.seed", 0, INT64_MAX));
  if (tl.shader_scene)
    if (const toml::node* n = video->get("adaptive"))
      r.fail(*n, "video.adaptive is not defined for a user's shader yet: use samples = N");
  parse_adaptive(r, *video, tl);
  return *scene;
}

void parse_output(const TomlReader& r, const toml::table& root, const SceneInfo& scene,
                  Timeline& tl) {
  tl.out_dir = "output/" + timeline_stem(tl.path);
  const toml::table* output = section(r, root, "output");
  if (!output) return;
  r.check_keys(*output, "[output]",
               {"dir", "frames", "video", "codec", "crf", "tiff_bits", "dpx_bits", "jpeg_quality",
                "exr_compression", "exr_bits", "passes", "audio", "audio_offset", "audio_fade"});

  if (const toml::node* n = output->get("dir")) {
    tl.out_dir = r.string(*n, "output.dir");
    if (tl.out_dir.empty()) r.fail(*n, "output.dir must not be empty");
    if (std::string problem = check_path_text("output.dir", tl.out_dir); !problem.empty())
      r.fail(*n, problem);
  }
  parse_frame_files(r, *output, tl);
  parse_passes(r, *output, scene, tl);
  parse_soundtrack(r, *output, tl);
  if (const toml::node* n = output->get("video")) tl.video = r.string(*n, "output.video");
  if (const toml::node* n = output->get("codec")) {
    const std::vector<std::string> codecs = video_codec_names();
    std::string c = r.string(*n, "output.codec");
    if (std::find(codecs.begin(), codecs.end(), c) == codecs.end())
      r.fail(*n,
             "unknown codec '" + c + "': use " + join(codecs, " or ") + did_you_mean(c, codecs));
    tl.codec = c;
  }
  if (const toml::node* n = output->get("crf")) tl.crf = int(r.integer_in(*n, "output.crf", 0, 51));
}

void parse_color(const TomlReader& r, const toml::table& root, Timeline& tl) {
  const toml::table* color = section(r, root, "color");
  if (!color) return;
  r.check_keys(*color, "[color]", {"config", "display", "view"});
  for (auto [key, field] : {std::pair{"config", &tl.color_config},
                            std::pair{"display", &tl.display}, std::pair{"view", &tl.view}}) {
    if (const toml::node* n = color->get(key)) {
      *field = r.string(*n, std::string("color.") + key);
      if (field->empty()) r.fail(*n, std::string("color.") + key + " must not be empty");
    }
  }
}

}  // namespace sdfreel
