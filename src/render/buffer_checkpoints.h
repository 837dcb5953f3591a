#pragma once
// Checkpoints of a user's shader's buffers (docs/shaders.md): the float state that frames
// 0..k-1 leave in Buffers A-D, kept every N frames in the render folder, so that a render, a
// shard, a resume or verify that starts at frame k replays from the latest checkpoint at or
// before k instead of from frame 0. The bits are the same either way.
#include <array>
#include <optional>
#include <vector>

namespace sdfreel {

// What a replay of frames 0..next_frame-1 leaves in the buffers, by PassKind (Buffer A..D, Cube
// A): RGBA32F texels in GL's row order (Cube A: its six faces in GL's order, cube_size square);
// empty for a buffer the shader does not have.
struct BufferState {
  int next_frame = 0;
  int width = 0, height = 0;
  int cube_size = 0;
  std::array<std::vector<float>, 5> buffers;
};

class BufferCheckpoints {
 public:
  virtual ~BufferCheckpoints() = default;
  // Checkpoints are kept before every frame that is a multiple of this (> 0).
  virtual int every() const = 0;
  // The latest checkpoint whose next_frame lies in [from, to] and whose check passes, of this size.
  // One that fails its check is skipped with a warning; nullopt when there is none.
  virtual std::optional<BufferState> latest(int from, int to, int width, int height) = 0;
  // True when a good checkpoint before `next_frame` is kept already (or none can be written).
  virtual bool has(int next_frame) = 0;
  // Keeps `state`, atomically; a failure (a full disk) is a warning, never an error.
  virtual void save(const BufferState& state) = 0;
};

}  // namespace sdfreel
