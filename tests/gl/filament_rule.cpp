#include "gl/filament_rule.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "io/frame_files.h"

namespace sdfreel::test {

ImageRGB16 filament_display(const ImageRGBA& linear) {
  ImageRGB16 out(linear.width, linear.height);
  for (size_t i = 0, o = 0; i < linear.pixels.size(); i += 4)
    for (int c = 0; c < 3; ++c) {
      const double v = std::clamp(double(linear.pixels[i + size_t(c)]), 0.0, 1.0);
      out.pixels[o++] = uint16_t(std::lround(std::pow(v, 1.0 / 2.2) * 65535.0));
    }
  return out;
}

FilamentVerdict filament_compare(const ImageRGBA& cpu_linear, const ImageRGBA& gl_linear,
                                 const std::string& dir_name) {
  const ImageRGB16 cpu = filament_display(cpu_linear), gl = filament_display(gl_linear);
  const ToleranceVerdict rule = filament_rule(cpu, gl);
  FilamentVerdict v;
  v.mean = rule.difference.mean;
  v.max = rule.difference.max;
  v.share_over_5 = rule.share_over_5;
  v.pass = rule.pass;
  const char* keep = std::getenv("SDFREEL_TEST_IMAGES");
  if (keep || !v.pass) {
    v.images =
        (keep ? std::string(keep) : ::testing::TempDir() + "sdfreel-agreement") + "/" + dir_name;
    std::filesystem::create_directories(v.images);
    write_png16_atomic(v.images + "/cpu.png", cpu);
    write_png16_atomic(v.images + "/gl.png", gl);
    write_png16_atomic(v.images + "/diff.png", difference_image(cpu, gl, 16.0));
  }
  return v;
}

}  // namespace sdfreel::test
