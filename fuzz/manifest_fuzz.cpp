// libFuzzer target: the manifest.json, manifest.journal and framemd5 readers (everything
// `verify --manifest` reads), and the framemd5 writer on what they accept. Malformed input must end in std::runtime_error (exit 2 for a manifest named
// on the command line); an accepted manifest must survive a write/read round trip unchanged.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "io/framemd5_reader.h"
#include "io/manifest.h"
#include "io/manifest_journal.h"

namespace {

bool same_frames(const sdfreel::Manifest& a, const sdfreel::Manifest& b) {
  if (a.frames.size() != b.frames.size()) return false;
  for (const auto& [i, f] : a.frames) {
    auto it = b.frames.find(i);
    if (it == b.frames.end() || it->second.display_md5 != f.display_md5 ||
        it->second.linear_hash != f.linear_hash)
      return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // A framemd5 reader must accept or throw Framemd5Error, nothing else; what it accepts has MD5s.
  try {
    for (const auto& [pts, frame] : sdfreel::parse_framemd5(text).frames)
      if (pts < 0 || frame.md5.size() != 32) std::abort();
  } catch (const sdfreel::Framemd5Error&) {
  }
  // Bytes after the first NUL, if any, are a journal for the manifest before it.
  const size_t nul = text.find('\0');
  const std::string manifest_text = text.substr(0, nul);
  sdfreel::Manifest m;
  try {
    m = sdfreel::manifest_from_json(manifest_text);
  } catch (const std::runtime_error&) {
    return 0;
  }
  if (nul != std::string::npos)
    sdfreel::merge_journal_text(text.substr(nul + 1), sdfreel::render_key(m.header), m);
  (void)sdfreel::framemd5_text(m);
  const sdfreel::Manifest again = sdfreel::manifest_from_json(sdfreel::manifest_to_json(m));
  if (!same_frames(m, again) || !again.header.same_render_as(m.header)) std::abort();
  return 0;
}
