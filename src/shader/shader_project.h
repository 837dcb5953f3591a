#pragma once
// A user's shader (docs/shaders.md): Shadertoy's tabs (Common, Buffers A-D, Cube A, Image) with
// their code verbatim and each pass's four channels, read from a folder of tabs, one .glsl file
// or Shadertoy's JSON export, plus the timeline's [shader] settings. Plain data: the GL backend
// (backends/gl/shadertoy_*) runs it, the timeline validates [params] against its uniforms.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "render/image.h"
#include "shader/cube_faces.h"

namespace sdfreel {

// Shadertoy's order of execution: every buffer, then Cube A, then Image.
enum class PassKind { BufferA, BufferB, BufferC, BufferD, CubeA, Image };
constexpr int kPassKinds = 6;

// "buffer_a", ..., "cube_a", "image": file stems of the tabs and names in [channels.NAME].
const char* pass_name(PassKind kind);

enum class ChannelKind { None, Pass, Texture, Cubemap };
enum class Filter { Nearest, Linear, Mipmap };
enum class Wrap { Clamp, Repeat };

struct ChannelBinding {
  ChannelKind kind = ChannelKind::None;
  PassKind pass = PassKind::BufferA;  // kind Pass: the buffer (or Cube A) read
  std::vector<std::string> files;     // Texture: one; Cubemap: six faces (+x -x +y -y +z -z) or one
  Filter filter = Filter::Linear;
  Wrap wrap = Wrap::Clamp;
  bool vflip = false;
  bool srgb = false;  // Texture: 8/16-bit texels decoded from sRGB to linear (the site's sampler)
  std::shared_ptr<const ImageRGBA> image;  // Texture: its texels, read at load (channel_images.h)
  std::shared_ptr<const CubeFaces> cube;   // Cubemap: its faces, read at load
  std::string origin_file;  // where it was bound, for messages (line and column 0 when unknown)
  int origin_line = 0, origin_column = 0;
};

// Shadertoy's defaults: buffers linear and clamped, textures mipmapped, repeated and flipped
// (its loader's defaults), cubemaps mipmapped and clamped.
ChannelBinding default_binding(ChannelKind kind);

struct ShaderPass {
  PassKind kind = PassKind::Image;
  std::string file;    // where its code came from, for compile errors
  std::string source;  // verbatim
  int first_line = 1;  // line of `file` where `source` starts (1 for a tab file; JSON: 1)
  std::array<ChannelBinding, 4> channels;
};

struct ShaderProject {
  std::string path;                        // as the timeline names it, resolved
  std::string common_file, common_source;  // "" when there is no Common tab
  std::vector<ShaderPass> passes;          // in PassKind order; Image always, last
  // [shader] settings
  bool display_referred = true;  // output = "display": the numbers written are sRGB display values
  std::array<double, 4> date{2026.0, 0.0, 1.0, 0.0};  // iDate at TIME 0: year, month 0-11, day, s
  double sample_rate = 44100.0;
  bool non_finite_black = true;           // NaN/Inf pixels written black (else the frame fails)
  std::vector<std::string> texture_dirs;  // where a JSON input's file is looked for
  // The buffers' state is kept before every Nth frame (feedback only; 0: never).
  int checkpoint_every = 60;
  int cube_size = 1024;  // Cube A's faces, in texels (Shadertoy's 1024)

  const ShaderPass* find(PassKind kind) const;
  // True when some pass reads a buffer that has not run yet in the frame (itself or a later one):
  // its frames then depend on the frames before them.
  bool has_feedback() const;
};

}  // namespace sdfreel
