#pragma once
// The parsed, validated timeline (docs/timeline.md). Parsing and validation live in parse.cpp;
// errors are InputError with file:line:column.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/adaptive_sampling.h"
#include "render/camera.h"
#include "render/quality.h"
#include "timeline/curve.h"
#include "timeline/frame_file_options.h"

namespace sdfreel {

// Bad input: printed as "FILE:LINE:COLUMN: error: WHAT", exit status 2.
struct InputError : std::runtime_error {
  std::string file;
  int line = 0, column = 0;  // 0 when unknown
  InputError(std::string file, int line, int column, const std::string& what);
  std::string formatted() const;  // FILE:LINE:COLUMN: error: WHAT (omits 0 line/column)
};

struct Rational {
  int64_t num = 30, den = 1;
  double value() const { return double(num) / double(den); }
};

struct SceneInfo;

struct CameraKey {
  double t = 0.0;
  CameraPose pose;
};

struct CameraPathTables;  // curves and arc-length table built from the keys (camera_path.cpp)

struct CameraPath {
  Interp interp = Interp::CatmullRom;
  bool constant_speed = false;  // speed = "constant": arc-length re-parameterisation
  std::vector<CameraKey> keys;  // empty: the scene's default camera
  // Builds the curves and the arc-length table once (the parser calls it); call again after
  // changing the fields. Without it, sample() builds them for every call.
  void prepare();
  CameraPose sample(double t, const CameraPose& fallback) const;

 private:
  std::shared_ptr<const CameraPathTables> tables_;  // shared by copies: read-only
};

struct ParamTrack {
  std::string name;
  Curve curve;  // a constant is a one-key curve
};

struct Timeline {
  std::string path;    // as given on the command line
  std::string sha256;  // of the file's bytes, lowercase hex
  // Of the parsed table written out canonically (toml++'s formatter: keys sorted, no comments,
  // one layout): what resume, shards and verify compare, so that a comment, whitespace or the
  // order of keys does not make a render's frames foreign.
  std::string parsed_sha256;

  // [video]
  std::string scene;   // a built-in scene's name, or "shader:PATH" for a user's shader
  std::string shader;  // [video] shader, resolved against the timeline's folder; "" for a scene
  // The user's shader as a scene (params from its uniforms), made by the ShaderLoader.
  std::shared_ptr<const SceneInfo> shader_scene;
  Rational fps;
  double duration = 10.0;
  int width = 1280, height = 720;
  // Where [video] resolution stands in the file (0: not there, or overridden): h264's even-size
  // rule is checked only when a video is made (validate_overrides), and points here.
  int resolution_line = 0, resolution_column = 0;
  int samples = 4;
  AdaptiveSampling adaptive;  // enabled: per-pixel adaptive sampling instead of `samples`
  // Which of adaptive's numbers the file gave; the others are its quality preset's and follow the
  // frame's size, which a command may still change (adaptive_at_size).
  struct AdaptiveGiven {
    bool minimum = false, maximum = false, threshold = false;
  } adaptive_given;
  Quality quality = Quality::Final;
  uint64_t seed = 1;

  // [output]
  std::string out_dir;  // default: output/<timeline file stem>
  bool write_exr = true, write_png = true;
  // Frame files OpenImageIO writes ("tif", "dpx", "jpg", ...: io/frame_formats.h), with where each
  // name stands in the file: a name beyond the known ones is checked against OpenImageIO's
  // writers when the command starts (validate_frame_formats), which this library does not link.
  struct OtherFrames {
    std::string ext;
    int line = 0, column = 0;
  };
  std::vector<OtherFrames> other_frames;
  FrameFileOptions frame_options;
  std::string video;  // "" = no video
  // [output] audio: a soundtrack under the video (io/audio_track.h), its path resolved against
  // the timeline's folder, with where the key stands (it is opened when the command starts).
  struct Soundtrack {
    std::string path;     // "" = none
    double offset = 0.0;  // seconds into the audio at video time 0
    double fade = 0.0;    // seconds of fade-out at the video's end (0: none)
    int line = 0, column = 0;
  } audio;
  std::string codec = "h264";  // h264 | ffv1 | prores
  int crf = 18;

  // [color]
  std::string color_config = "builtin";
  std::string display = "sRGB";
  std::string view = "ACES 1.0 - SDR Video";

  std::optional<Curve> time;  // TIME(t); empty = identity
  CameraPath camera;
  std::vector<ParamTrack> params;

  int frame_count() const;  // round(duration * fps)
  // The adaptive sampling a frame of width x height gets: the given numbers, the rest from
  // adaptive_preset(quality, width, height) (`final` samples small frames more).
  AdaptiveSampling adaptive_at_size() const;
  double video_time(int frame) const;  // frame / fps
  double scene_time(int frame) const;  // TIME at video_time(frame)
};

// Hooks the parser needs from the rest of the program, so this library does not depend on OCIO.
struct ColorChecker {
  // Returns an error message, or "" when config/display/view exist.
  virtual std::string check(const std::string& config, const std::string& display,
                            const std::string& view) const = 0;
  virtual ~ColorChecker() = default;
};

struct ShaderLoader;  // timeline/shader_loader.h

// Reads, parses and validates a timeline file. Throws InputError on any bad input (spec's list).
// `scenes`: the scenes a timeline may name (all_scenes() in the program), a hook like `color`, so
// that this library does not link the scenes.
// `shaders`: nullptr refuses `[video] shader`.
Timeline load_timeline(const std::vector<SceneInfo>& scenes, const std::string& path,
                       const ColorChecker* color, const ShaderLoader* shaders = nullptr);
// The same on the file's bytes already in memory (`path` names it in messages; fuzzing uses it).
Timeline parse_timeline(const std::vector<SceneInfo>& scenes, const std::string& path,
                        const std::string& text, const ColorChecker* color,
                        const ShaderLoader* shaders = nullptr);

// Validates a timeline after command-line overrides: resolution, samples and, when `makes_video`,
// the codec's size rule (h264's even sides; no other output has one). Throws InputError with the
// timeline path (and [video] resolution's place for the size rule, when the size is the file's).
void validate_overrides(const Timeline& tl, bool makes_video);

}  // namespace sdfreel
