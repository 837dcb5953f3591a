// Error metrics of the bench on images whose answers are known by construction.
#include "bench/metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sdfreel::bench {
namespace {

ImageRGB16 filled(int w, int h, uint16_t v) {
  ImageRGB16 img(w, h);
  for (uint16_t& p : img.pixels) p = v;
  return img;
}

TEST(Metrics, IdenticalImagesHaveZeroErrorAndInfinitePsnr) {
  ImageRGB16 a = filled(8, 4, 1234);
  a.pixels[5] = 60000;
  ErrorAccumulator acc;
  acc.add(a, a);
  const ErrorMetrics m = acc.result();
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.mean_abs_error, 0.0);
  EXPECT_EQ(m.p99_abs_error, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr_db) && m.psnr_db > 0.0);
}

TEST(Metrics, ConstantOffsetGivesItsPsnr) {
  // Every value off by 655.35 / 65535 = 0.01: RMSE 0.01, PSNR 40 dB.
  const ImageRGB16 ref = filled(16, 9, 10000);
  ImageRGB16 img = ref;
  for (size_t i = 0; i < img.pixels.size(); ++i)
    img.pixels[i] = uint16_t(i % 2 ? 10000 + 655 : 10000 - 656);  // alternating sign, ~0.01
  ErrorAccumulator acc;
  acc.add(img, ref);
  const ErrorMetrics m = acc.result();
  const double expected = std::sqrt((655.0 * 655.0 + 656.0 * 656.0) / 2.0) / 65535.0;
  EXPECT_NEAR(m.rmse, expected, 1e-12);
  EXPECT_NEAR(m.psnr_db, -20.0 * std::log10(expected), 1e-9);
  EXPECT_NEAR(m.psnr_db, 40.0, 0.01);
  EXPECT_NEAR(m.mean_abs_error, (655.0 + 656.0) / 2.0 / 65535.0, 1e-12);
  EXPECT_NEAR(m.p99_abs_error, 656.0 / 65535.0, 1e-7);
}

TEST(Metrics, NinetyNinthPercentileIgnoresTheTopPercent) {
  // 1000 values (a 1000 x 1 image has 3000: use 10 x 10 x 3 = 300 and 100 x 10 x 3 = 3000).
  const ImageRGB16 ref = filled(100, 10, 0);
  ImageRGB16 few = ref;  // 29 of 3000 values off (< 1%): the 99th percentile is still 0
  for (int i = 0; i < 29; ++i) few.pixels[size_t(i) * 97] = 65535;
  ErrorAccumulator a;
  a.add(few, ref);
  EXPECT_EQ(a.result().p99_abs_error, 0.0);
  EXPECT_GT(a.result().rmse, 0.0);
  ImageRGB16 many = ref;  // 31 of 3000 values off (> 1%): the 99th percentile is the error
  for (int i = 0; i < 31; ++i) many.pixels[size_t(i) * 97] = 65535;
  ErrorAccumulator b;
  b.add(many, ref);
  EXPECT_FLOAT_EQ(float(b.result().p99_abs_error), 1.0f);
}

TEST(Metrics, AccumulatesOverFrames) {
  const ImageRGB16 ref = filled(4, 4, 0);
  ErrorAccumulator acc;
  acc.add(ref, ref);                  // error 0 on half of the values
  acc.add(filled(4, 4, 65535), ref);  // error 1 on the other half
  EXPECT_EQ(acc.values(), size_t(2 * 4 * 4 * 3));
  EXPECT_NEAR(acc.result().rmse, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(acc.result().mean_abs_error, 0.5, 1e-12);
}

TEST(Metrics, SizeMismatchThrows) {
  ErrorAccumulator acc;
  EXPECT_THROW(acc.add(filled(4, 4, 0), filled(4, 5, 0)), std::invalid_argument);
  HitMissAccumulator hits;
  EXPECT_THROW(hits.add(ImageRGBA(2, 2), ImageRGBA(3, 2)), std::invalid_argument);
}

TEST(Metrics, HitMissCountsPixelsWhoseIdsDiffer) {
  ImageRGBA ref(10, 10), mask(10, 10);
  for (int i = 0; i < 100; ++i) ref.pixels[size_t(i) * 4] = float(i % 3);
  mask = ref;
  HitMissAccumulator same;
  same.add(mask, ref);
  EXPECT_EQ(same.fraction(), 0.0);
  // 7 pixels change id; changing only green or blue (not the id channel) does not count.
  for (int i = 0; i < 7; ++i) mask.pixels[size_t(i) * 13 * 4] += 1.0f;
  mask.pixels[size_t(99) * 4 + 1] = 5.0f;
  HitMissAccumulator acc;
  acc.add(mask, ref);
  EXPECT_DOUBLE_EQ(acc.fraction(), 0.07);
}

TEST(Metrics, PsnrFromRmse) {
  EXPECT_NEAR(psnr_from_rmse(0.1), 20.0, 1e-12);
  EXPECT_NEAR(psnr_from_rmse(0.001), 60.0, 1e-9);
  EXPECT_TRUE(std::isinf(psnr_from_rmse(0.0)));
}

}  // namespace
}  // namespace sdfreel::bench
