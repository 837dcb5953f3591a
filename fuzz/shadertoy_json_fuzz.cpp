// libFuzzer target: Shadertoy's JSON reader (a user's shader named by `[video] shader = "x.json"`).
// Any bytes must end in a ShaderProject or an InputError (exit 2), nothing else; what it accepts
// has its Image pass last, passes in Shadertoy's order, each once, and channels that read passes
// it has or nothing.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "shader/shadertoy_json.h"
#include "timeline/timeline.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sdfreel::ShaderProject p;
  try {
    // Texture inputs are looked for beside "fuzz.json": in a folder that does not exist.
    p = sdfreel::read_shadertoy_json("/nonexistent/fuzz.json", text, {});
  } catch (const sdfreel::InputError&) {
    return 0;
  }
  if (p.passes.empty() || p.passes.back().kind != sdfreel::PassKind::Image) std::abort();
  for (size_t i = 1; i < p.passes.size(); ++i)
    if (int(p.passes[i - 1].kind) >= int(p.passes[i].kind)) std::abort();
  for (const sdfreel::ShaderPass& pass : p.passes)
    for (const sdfreel::ChannelBinding& c : pass.channels)
      if (c.kind == sdfreel::ChannelKind::Pass && !p.find(c.pass)) std::abort();
  return 0;
}
