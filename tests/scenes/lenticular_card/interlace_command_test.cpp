// `sdfreel interlace` end to end: the print it writes de-interlaces into the views it read, and
// bad input exits 2 with a message and writes nothing.
#include <gtest/gtest.h>

#include <filesystem>

#include "scenes/lenticular_card/interlace.h"
#include "scenes/lenticular_card/ppm.h"
#include "support/run.h"
#include "support/scratch.h"

namespace sdfreel::lenticular_card {
namespace {

namespace fs = std::filesystem;

Rgb8Image numbered_view(int v, int w, int h) {
  Rgb8Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = img.at(x, y);
      p[0] = uint8_t(40 * v), p[1] = uint8_t(20 * x), p[2] = uint8_t(30 * y);
    }
  return img;
}

class InterlaceCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    // A folder of its own per test: ctest runs them in parallel.
    dir_ = test::scratch_dir(std::string("interlace_") +
                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    for (int v = 0; v < 3; ++v) {
      views_.push_back(numbered_view(v, 5, 4));
      test::write_file(path("v" + std::to_string(v) + ".ppm"), encode_ppm(views_.back()));
    }
    test::write_file(path("small.ppm"), encode_ppm(numbered_view(0, 4, 4)));
  }
  std::string path(const std::string& name) const { return (fs::path(dir_) / name).string(); }
  void expect_refused(const std::string& args, const std::string& message) {
    const test::RunResult r = test::run_sdfreel("interlace " + args, dir_);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(path("out.ppm"))) << args;
  }
  std::string dir_;
  std::vector<Rgb8Image> views_;
};

TEST_F(InterlaceCommand, WritesAPrintThatDeinterlacesIntoTheViews) {
  const test::RunResult r =
      test::run_sdfreel("interlace v0.ppm v1.ppm v2.ppm -o out.ppm --lpi 10 --dpi 35", dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  Rgb8Image print;
  ASSERT_TRUE(read_ppm(path("out.ppm"), print));
  const InterlaceLayout layout = print_layout(3, 10.0, 35.0);
  EXPECT_EQ(print.width, print_width(layout, 5));
  EXPECT_EQ(print.height, print_height(layout, 4));
  const std::vector<Rgb8Image> back = deinterlace(print, layout, 5, 4);
  for (int v = 0; v < 3; ++v) EXPECT_EQ(back[v].rgb, views_[v].rgb) << "view " << v;
  // The pattern form reads the same files.
  ASSERT_EQ(
      test::run_sdfreel("interlace --pattern v%d.ppm --views 3 -o p.ppm --lpi 10 --dpi 35", dir_)
          .status,
      0);
  EXPECT_EQ(test::read_file(path("p.ppm")), test::read_file(path("out.ppm")));
}

TEST_F(InterlaceCommand, BadInputExitsTwoAndWritesNothing) {
  expect_refused("v0.ppm v1.ppm v2.ppm -o out.ppm --lpi 10 --dpi 20", "fewer than the 3 views");
  expect_refused("v0.ppm missing.ppm -o out.ppm --lpi 10 --dpi 35", "missing.ppm");
  expect_refused("v0.ppm small.ppm -o out.ppm --lpi 10 --dpi 35", "small.ppm");
  expect_refused("v0.ppm -o out.ppm --lpi 10 --dpi 35", "at least 2 views");
  expect_refused("v0.ppm v1.ppm --views 3 -o out.ppm --lpi 10 --dpi 35", "--views 3");
  expect_refused("--pattern v.ppm --views 3 -o out.ppm --lpi 10 --dpi 35", "no %d");
  expect_refused("v0.ppm v1.ppm -o out.ppm --lpi 0 --dpi 35", "lpi");
  const test::RunResult r =
      test::run_sdfreel("interlace v0.ppm v1.ppm -o out.nosuchformat --lpi 10 --dpi 35", dir_);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_FALSE(fs::exists(path("out.nosuchformat")));
}

}  // namespace
}  // namespace sdfreel::lenticular_card
