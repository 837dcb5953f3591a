#include "shader/shader_hash.h"

#include "shader/shader_files.h"
#include "timeline/sha256.h"

namespace sdfreel {

namespace {

// Length-prefixed, so that no two different projects concatenate to the same bytes.
void add(std::string& bytes, const std::string& part) {
  bytes += std::to_string(part.size()) + ":" + part;
}

}  // namespace

std::string shader_project_sha256(const ShaderProject& p) {
  std::string bytes;
  add(bytes, p.common_source);
  for (const ShaderPass& pass : p.passes) {
    add(bytes, pass_name(pass.kind));
    add(bytes, pass.source);
    for (const ChannelBinding& b : pass.channels) {
      add(bytes, std::to_string(int(b.kind)) + " " + std::to_string(int(b.pass)) + " " +
                     std::to_string(int(b.filter)) + " " + std::to_string(int(b.wrap)) + " " +
                     std::to_string(int(b.vflip)) + " " + std::to_string(int(b.srgb)));
      for (const std::string& f : b.files) add(bytes, read_shader_bytes(f));
    }
  }
  add(bytes, p.display_referred ? "display" : "linear");
  for (double d : p.date) add(bytes, std::to_string(d));
  add(bytes, std::to_string(p.sample_rate));
  add(bytes, p.non_finite_black ? "black" : "error");
  add(bytes, std::to_string(p.cube_size));
  return sha256_hex(bytes);
}

}  // namespace sdfreel
