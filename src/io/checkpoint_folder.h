#pragma once
// Checkpoints of a shader's buffers as files in the render folder (docs/shaders.md):
// <out>/checkpoints/buffers-NNNNN.ckpt holds the state before frame NNNNN. Each file carries the
// render's key (render_key: timeline, backend, library versions, resolution...), its frame, its
// size and a 64-bit checksum of its texels; one whose key, size or checksum does not match is
// never used. Written atomically (write_file_atomic), read only with `writable` false (verify).
#include <set>
#include <string>

#include "render/buffer_checkpoints.h"

namespace sdfreel {

class CheckpointFolder : public BufferCheckpoints {
 public:
  // Checkpoints before frames 1..frame_count-1 only (one before the end would serve nothing).
  CheckpointFolder(std::string dir, std::string key, int every, int frame_count, bool writable);
  int every() const override { return every_; }
  std::optional<BufferState> latest(int from, int to, int width, int height) override;
  bool has(int next_frame) override;
  void save(const BufferState& state) override;

  std::string path(int next_frame) const;  // dir/buffers-NNNNN.ckpt

 private:
  std::string dir_, key_;
  int every_, frame_count_;
  bool writable_;
  std::set<int> rejected_;  // failed their check: written again when the replay passes them
};

// The checkpoint file's bytes of `state` under `key`, and back. `read_checkpoint` returns why a
// file cannot be used ("" when it can) and fills `state` only then.
std::string encode_checkpoint(const BufferState& state, const std::string& key);
std::string decode_checkpoint(const std::string& bytes, const std::string& key, BufferState& state,
                              bool header_only = false);

}  // namespace sdfreel
