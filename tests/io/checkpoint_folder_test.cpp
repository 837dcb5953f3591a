// Checkpoint files of a shader's buffers (io/checkpoint_folder.h): what is written reads back
// bit for bit, and a file of another render, a torn or a corrupted one is never used: the latest
// good one before it is, and the bad one is written again when the replay passes it.
#include "io/checkpoint_folder.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "support/scratch.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;

BufferState state(int next_frame, float seed) {
  BufferState s{next_frame, 3, 2, 2, {}};
  for (size_t k : {size_t(0), size_t(2), size_t(4)}) {  // Buffers A and C, Cube A (six faces)
    s.buffers[k].resize(k == 4 ? 2 * 2 * 4 * 6 : 3 * 2 * 4);
    for (size_t i = 0; i < s.buffers[k].size(); ++i) s.buffers[k][i] = seed + float(i) * 0.1f + k;
  }
  s.buffers[2][5] = -1e30f;  // any float, as stored
  return s;
}

TEST(CheckpointFile, RoundTripsBitForBit) {
  const BufferState s = state(30, 0.5f);
  BufferState back;
  ASSERT_EQ(decode_checkpoint(encode_checkpoint(s, "key"), "key", back), "");
  EXPECT_EQ(back.next_frame, 30);
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.cube_size, 2);
  EXPECT_EQ(back.buffers, s.buffers);
}

TEST(CheckpointFile, RefusesAnotherRenderATornAndACorruptedFile) {
  const std::string bytes = encode_checkpoint(state(30, 0.5f), "key");
  BufferState back;
  EXPECT_EQ(decode_checkpoint(bytes, "other key", back), "made by a render of other settings");
  EXPECT_EQ(decode_checkpoint(bytes.substr(0, bytes.size() - 1), "key", back), "truncated");
  EXPECT_EQ(decode_checkpoint(bytes.substr(0, 20), "key", back), "truncated");
  std::string flipped = bytes;
  flipped[flipped.size() - 7] ^= 1;
  EXPECT_EQ(decode_checkpoint(flipped, "key", back), "a wrong checksum");
  EXPECT_EQ(decode_checkpoint("hello", "key", back), "not a checkpoint");
  // Found by fuzz_checkpoint: a byte of the reserved header field was accepted (and a re-encoded
  // file then differed from the one read).
  std::string reserved = bytes;
  reserved[8 + 8 + 3 + 4 * 5 + 1] = 1;  // magic, key size, "key", five int32s, reserved's byte 1
  EXPECT_EQ(decode_checkpoint(reserved, "key", back), "a damaged header");
  // And a Cube A of size 0 listed as present (its texels: none, read through a null pointer).
  BufferState empty_cube{30, 3, 2, 0, {}};
  empty_cube.buffers[0].assign(3 * 2 * 4, 1.0f);
  std::string cube_bytes = encode_checkpoint(empty_cube, "key");
  cube_bytes[8 + 8 + 3 + 4 * 4] |= 0x10;  // present: bit 4, Cube A
  EXPECT_EQ(decode_checkpoint(cube_bytes, "key", back), "a damaged header");
}

TEST(CheckpointFolder, LatestSkipsBadFilesAndRewritesThem) {
  const std::string dir = test::scratch_dir("checkpoint_folder");
  CheckpointFolder folder(dir, "key", 10, 100, true);
  EXPECT_FALSE(folder.latest(1, 99, 3, 2));
  for (int f : {10, 20, 30}) folder.save(state(f, float(f)));
  EXPECT_TRUE(folder.has(20));
  EXPECT_TRUE(folder.has(100)) << "none is kept before the end: it would serve nothing";
  EXPECT_FALSE(folder.has(40));
  std::optional<BufferState> s = folder.latest(1, 35, 3, 2);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->next_frame, 30);
  EXPECT_FALSE(folder.latest(31, 35, 3, 2)) << "none saves work from frame 31";
  EXPECT_FALSE(folder.latest(1, 35, 4, 2)) << "another size";
  // Corrupt 30: 20 is used instead, and 30 counts as missing until it is written again.
  std::string bytes = test::read_file(folder.path(30));
  bytes[bytes.size() - 1] ^= 1;
  test::write_file(folder.path(30), bytes);
  s = folder.latest(1, 35, 3, 2);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->next_frame, 20);
  EXPECT_EQ(s->buffers, state(20, 20.0f).buffers);
  EXPECT_FALSE(folder.has(30));
  folder.save(state(30, 30.0f));
  EXPECT_EQ(folder.latest(1, 35, 3, 2)->next_frame, 30);
  // Read only (verify): never writes.
  CheckpointFolder reader(dir + "/other", "key", 10, 100, false);
  EXPECT_TRUE(reader.has(10));
  reader.save(state(10, 1.0f));
  EXPECT_FALSE(fs::exists(dir + "/other"));
}

}  // namespace
}  // namespace sdfreel
