// libFuzzer target: the reader of a shader's buffer checkpoints (io/checkpoint_folder.h), which
// a render reads back from its folder, where a torn or corrupted file must be refused. Any bytes
// end in a reason or a state whose sizes agree with its header; what is accepted encodes back to
// the same bytes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "io/checkpoint_folder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace sdfreel;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  BufferState head, state;
  const std::string why_head = decode_checkpoint(bytes, "fuzz key", head, true);
  const std::string why = decode_checkpoint(bytes, "fuzz key", state);
  if (!why.empty()) return 0;
  if (!why_head.empty()) std::abort();  // a good file's header is good
  for (size_t k = 0; k < state.buffers.size(); ++k) {
    const size_t face = k == 4 ? size_t(state.cube_size) * size_t(state.cube_size) * 24
                               : size_t(state.width) * size_t(state.height) * 4;
    if (!state.buffers[k].empty() && state.buffers[k].size() != face) std::abort();
  }
  if (encode_checkpoint(state, "fuzz key") != bytes) std::abort();
  return 0;
}
