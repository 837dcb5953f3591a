// Issue 17 items 6-8 at the library level: per-frame manifest work is O(1) (a journal line, not a
// rewrite), torn journal lines are ignored, indices are range-checked, special files are refused.
#include "io/manifest_journal.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "io/bounded_read.h"
#include "io/manifest.h"

namespace sdfreel {
namespace {

namespace fs = std::filesystem;

struct Folder {
  fs::path path;
  explicit Folder(const std::string& name)
      : path(fs::temp_directory_path() / ("sdfreel-mj-" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Folder() { fs::remove_all(path); }
  std::string str() const { return path.string(); }
};

ManifestHeader header(int frames) {
  ManifestHeader h;
  h.timeline_sha256 = std::string(64, 'a');
  h.timeline_parsed_sha256 = std::string(64, 'd');
  h.scene = "sdf_morph";
  h.backend = "cpu";
  h.width = 64;
  h.height = 36;
  h.frame_count = frames;
  h.frame_files = {"png"};
  return h;
}

ManifestFrame frame(int i) {
  return ManifestFrame{i, i / 30.0, i / 30.0, std::string(32, 'b'), std::string(32, 'c'), 0.5, 10};
}

double seconds_to_record(const std::string& dir, const ManifestHeader& h, int from, int count) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = from; i < from + count; ++i) record_frame(dir, h, frame(i));
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Recording into a folder whose manifest lists 30,000 frames costs about what it costs into an
// empty one. Before the fix every frame re-read and rewrote the whole manifest (about 10 MB here).
TEST(ManifestJournal, RecordingAFrameDoesNotGrowWithTheManifest) {
  const ManifestHeader h = header(100000);
  Folder empty("empty"), full("full");
  consolidate_manifest(empty.str(), h);
  Manifest big{h, {}};
  for (int i = 0; i < 30000; ++i) big.frames[i] = frame(i);
  std::ofstream(full.str() + "/manifest.json") << manifest_to_json(big);
  consolidate_manifest(full.str(), h);
  const double small_cost = seconds_to_record(empty.str(), h, 50000, 40);
  const double big_cost = seconds_to_record(full.str(), h, 50000, 40);
  EXPECT_LT(big_cost, 3 * small_cost + 0.05)
      << "40 frames took " << big_cost << " s beside 30,000 listed frames, " << small_cost
      << " s beside none";
  const auto m = read_manifest(full.str() + "/manifest.json");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->frames.size(), 30040u);  // the journal's frames count before consolidation
  consolidate_manifest(full.str(), h);
  EXPECT_EQ(fs::file_size(full.str() + "/manifest.journal"), 0u);
  EXPECT_EQ(read_manifest_json(full.str() + "/manifest.json")->frames.size(), 30040u);
}

TEST(ManifestJournal, TornAndForeignLinesAreIgnoredAndLaterLinesStillCount) {
  const ManifestHeader h = header(10);
  Folder dir("torn");
  consolidate_manifest(dir.str(), h);
  record_frame(dir.str(), h, frame(1));
  // A kill mid-append: half a line, no newline.
  std::ofstream(dir.str() + "/manifest.journal", std::ios::app)
      << "{\"render\": \"" << render_key(h);
  record_frame(dir.str(), h, frame(2));
  ManifestHeader other = h;
  other.samples = 4;
  record_frame(dir.str(), other, frame(3));
  const auto m = read_manifest(dir.str() + "/manifest.json");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->frames.size(), 2u);
  EXPECT_TRUE(m->frames.count(1) && m->frames.count(2));
}

TEST(ManifestJournal, IndexOutsideTheTimelineIsRefusedNotWrapped) {
  Manifest m{header(4), {}};
  m.frames[0] = frame(0);
  std::string text = manifest_to_json(m);
  text.replace(text.find("\"index\": 0"), 10, "\"index\": 1099511627776");
  EXPECT_THROW(manifest_from_json(text), std::runtime_error);
  text.replace(text.find("\"index\": 1099511627776"), 22, "\"index\": -1");
  EXPECT_THROW(manifest_from_json(text), std::runtime_error);
}

// Found by fuzz_manifest: a number too big for 64 bits parses as a double, whose conversion to
// int was undefined; a wide integer narrowed to int wrapped (frame_count 2^32 + 4 read as 4).
TEST(ManifestJournal, HugeFractionalOrWideNumbersAreRefusedNotConverted) {
  Manifest m{header(4), {}};
  m.frames[0] = frame(0);
  const std::string good = manifest_to_json(m);
  ASSERT_NO_THROW(manifest_from_json(good));
  auto with = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  EXPECT_THROW(manifest_from_json(with("\"samples\": 1", "\"samples\": " + std::string(40, '6'))),
               std::runtime_error);
  EXPECT_THROW(manifest_from_json(with("\"frame_count\": 4", "\"frame_count\": 4294967300")),
               std::runtime_error);
  EXPECT_THROW(manifest_from_json(with("\"frame_count\": 4", "\"frame_count\": 4.5")),
               std::runtime_error);
  EXPECT_THROW(manifest_from_json(with("64,", "1e300,")), std::runtime_error);
  EXPECT_THROW(manifest_from_json(with("\"index\": 0", "\"index\": 18446744073709551615")),
               std::runtime_error);
  EXPECT_THROW(manifest_from_json(with("\"fps\": \"30/1\"", "\"fps\": \"99999999999999999999/1\"")),
               std::runtime_error);
}

TEST(BoundedRead, RefusesFifosDevicesAndOversizedFiles) {
  Folder dir("bounded");
  const std::string fifo = dir.str() + "/fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  EXPECT_THROW(read_regular_file(fifo, 1024), std::runtime_error);  // returns, does not block
  EXPECT_THROW(read_regular_file("/dev/zero", 1024), std::runtime_error);
  std::ofstream(dir.str() + "/big") << std::string(2000, 'x');
  EXPECT_THROW(read_regular_file(dir.str() + "/big", 1024), std::runtime_error);
  EXPECT_EQ(read_regular_file(dir.str() + "/big", 4096)->size(), 2000u);
  EXPECT_FALSE(read_regular_file(dir.str() + "/missing", 4096));
}

}  // namespace
}  // namespace sdfreel
