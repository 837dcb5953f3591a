// Issue 17: bench.csv, the micro-benchmark CSV and the reference cache are written like frames:
// every write checked (an injected ENOSPC at each operation in turn fails the call, naming the
// file, and publishes nothing torn), and under a temporary name unique to the writer (two writers
// of one file both succeed, and the file is one writer's whole text).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include "bench/csv.h"
#include "bench/reference_cache.h"
#include "io/fault_injection.h"

namespace sdfreel::bench {
namespace {

namespace fs = std::filesystem;

std::string fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("sdfreel_write_faults_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Names in `dir` (recursively) that are not one of `allowed`: temporaries left behind.
std::vector<std::string> strays(const std::string& dir, const std::vector<std::string>& allowed) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) out.push_back(name);
  }
  return out;
}

std::vector<BenchRow> rows(const std::string& scene, int n) {
  std::vector<BenchRow> out(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    out[size_t(i)].scene = scene;
    out[size_t(i)].preset = "p" + std::to_string(i);
    out[size_t(i)].seconds_per_frame = 0.5 + i;
  }
  return out;
}

std::string csv_text(const std::vector<BenchRow>& r) {
  std::ostringstream s;
  write_csv(s, r);
  return s.str();
}

// Restores "no injected faults" however the test ends.
struct NoFaultsAfter {
  ~NoFaultsAfter() { set_io_fault_at(0); }
};

TEST(BenchWrites, CsvFailsAtEveryWriteOperationAndNeverPublishesATornFile) {
  NoFaultsAfter guard;
  const std::string dir = fresh_dir("csv");
  const std::string path = dir + "/bench.csv";
  const std::string old_text = csv_text(rows("old", 1)), new_text = csv_text(rows("new", 400));
  int n = 1;
  for (; n < 50; ++n) {
    write_csv_file(path, rows("old", 1));
    set_io_fault_at(n);
    try {
      write_csv_file(path, rows("new", 400));
      break;  // n is past the last operation
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("No space left"), std::string::npos) << e.what();
    }
    set_io_fault_at(0);
    const std::string now = read_all(path);
    EXPECT_TRUE(now == old_text || now == new_text) << "fault " << n << ": torn bench.csv";
    EXPECT_EQ(strays(dir, {"bench.csv"}), std::vector<std::string>()) << "fault " << n;
  }
  set_io_fault_at(0);
  EXPECT_GE(n, 4) << "the CSV does not go through the checked writer (write, fsync, close, rename)";
  EXPECT_EQ(read_all(path), new_text);
  fs::remove_all(dir);
}

TEST(BenchWrites, ReferenceCacheFailsAtEveryWriteOperationAndLoadsOnlyWholeFrames) {
  NoFaultsAfter guard;
  const std::string dir = fresh_dir("reference");
  ImageRGB16 display(17, 9);
  ImageRGBA mask(17, 9);
  for (size_t i = 0; i < display.pixels.size(); ++i) display.pixels[i] = uint16_t(i * 7919 + 3);
  for (size_t i = 0; i < 17 * 9; ++i) mask.pixels[i * 4] = float(i % 5);
  int n = 1;
  for (; n < 50; ++n) {
    fs::remove_all(dir + "/reference");
    const ReferenceCache cache(dir, reference_key("t", "s", 17, 9));
    set_io_fault_at(n);
    bool stored = true;
    try {
      cache.store(3, display, mask);
    } catch (const std::runtime_error& e) {
      stored = false;
      EXPECT_NE(std::string(e.what()).find("No space left"), std::string::npos) << e.what();
    }
    set_io_fault_at(0);
    ImageRGB16 d;
    ImageRGBA m;
    if (cache.load(3, 17, 9, d, m)) {
      EXPECT_EQ(d.pixels, display.pixels) << "fault " << n;
    }
    EXPECT_EQ(strays(dir, {"00003.png", "00003.mask.png"}), std::vector<std::string>())
        << "fault " << n;
    if (stored) break;
  }
  EXPECT_GE(n, 8) << "the reference files do not go through the checked writer";
  fs::remove_all(dir);
}

TEST(BenchWrites, TwoWritersOfOneCsvBothSucceedAndOneWholeTextWins) {
  const std::string dir = fresh_dir("concurrent");
  const std::string path = dir + "/bench.csv";
  const std::vector<BenchRow> a = rows("a", 300), b = rows("b", 200);
  std::string errors;
  std::mutex m;
  auto writer = [&](const std::vector<BenchRow>& r) {
    for (int i = 0; i < 40; ++i) try {
        write_csv_file(path, r);
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(m);
        errors += std::string(e.what()) + "\n";
      }
  };
  std::thread t1(writer, a), t2(writer, b);
  t1.join();
  t2.join();
  EXPECT_EQ(errors, "");
  const std::string now = read_all(path);
  EXPECT_TRUE(now == csv_text(a) || now == csv_text(b)) << "a mixed or torn bench.csv";
  EXPECT_EQ(strays(dir, {"bench.csv"}), std::vector<std::string>());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sdfreel::bench
