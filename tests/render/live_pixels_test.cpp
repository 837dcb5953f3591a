// Adaptive sampling's decisions (render/live_pixels.h) do not depend on how many threads take
// them: on a frame of random sums, with regions that settle and edges that do not, every round
// leaves the same pixels live with the same counts at 1, 2, 3 and 8 threads, and the same
// decisions as a plain per-pixel loop over the documented rule; all_live() holds until the first
// pixel stops.
#include "render/live_pixels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace sdfreel {
namespace {

constexpr int W = 77, H = 53;  // rows not a multiple of a task's rows

// Sums after `taken` samples: a smooth gradient with noise that shrinks with the sample count,
// a bright disc (an edge) and pixels where even and odd samples disagree.
void fill_sums(int taken, std::mt19937& rng, ImageRGBA& sum, ImageRGBA& odd) {
  std::normal_distribution<float> noise(0.0f, 0.3f / float(taken));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool disc = (x - 40) * (x - 40) + (y - 25) * (y - 25) < 150;
      const float base = disc ? 4.0f : 0.02f * float(x + y);
      for (int c = 0; c < 3; ++c) {
        const float mean = std::max(0.0f, base + noise(rng));
        sum.at(x, y)[c] = mean * float(taken);
        const float odd_mean = (x * 7 + y) % 11 == 0 ? mean * 1.5f : mean;
        odd.at(x, y)[c] = odd_mean * float(taken / 2);
      }
    }
}

// The rule of adaptive_sampling.h, pixel by pixel, for the pixels live in `live`.
std::vector<uint8_t> plain_decisions(const AdaptiveSampling& a, int taken, const ImageRGBA& sum,
                                     const ImageRGBA& odd, std::vector<glm::vec3>& display,
                                     const std::vector<uint8_t>& live) {
  for (size_t i = 0; i < live.size(); ++i)
    if (live[i])
      display[i] =
          display_value(glm::vec3(sum.pixels[i * 4], sum.pixels[i * 4 + 1], sum.pixels[i * 4 + 2]) *
                        (1.0f / float(taken)));
  std::vector<uint8_t> next = live;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      if (!live[i]) continue;
      float contrast = 0.0f;
      for (int j = std::max(y - 1, 0); j <= std::min(y + 1, H - 1); ++j)
        for (int k = std::max(x - 1, 0); k <= std::min(x + 1, W - 1); ++k)
          contrast = std::max(contrast, display_difference(display[i], display[size_t(j) * W + k]));
      const glm::vec3 s(sum.at(x, y)[0], sum.at(x, y)[1], sum.at(x, y)[2]);
      const glm::vec3 o(odd.at(x, y)[0], odd.at(x, y)[1], odd.at(x, y)[2]);
      const float error = std::max(own_error(taken, s, o), edge_error(taken, contrast));
      next[i] = needs_more_samples(a, taken, error) ? 1 : 0;
    }
  return next;
}

TEST(LivePixels, DecisionsAreTheRuleAtAnyThreadCount) {
  AdaptiveSampling a;
  a.enabled = true;
  a.minimum = 1;
  a.maximum = 16;
  a.threshold = 0.02f;
  std::vector<LivePixels> runs;
  for (int threads : {1, 2, 3, 8}) runs.emplace_back(a, W, H, threads);
  EXPECT_TRUE(runs[0].all_live());
  std::vector<glm::vec3> display(size_t(W) * H);
  std::vector<uint8_t> want(size_t(W) * H, 1);
  std::mt19937 rng(3);
  ImageRGBA sum(W, H), odd(W, H);
  int rounds = 0, stopped_somewhere = 0;
  for (int taken = runs[0].round_end(); taken < a.maximum; taken = runs[0].round_end()) {
    fill_sums(taken, rng, sum, odd);
    want = plain_decisions(a, taken, sum, odd, display, want);
    const int want_live = int(std::count(want.begin(), want.end(), 1));
    for (LivePixels& run : runs) {
      EXPECT_EQ(run.decide(taken, sum, odd), want_live) << "taken " << taken;
      EXPECT_EQ(run.mask(), want) << "taken " << taken;
      EXPECT_EQ(run.counts(), runs[0].counts());
      // all_live (the CPU's plain sum loops) until a decision stops a pixel, never after.
      EXPECT_EQ(run.all_live(), stopped_somewhere == 0 && want_live == W * H) << "taken " << taken;
    }
    stopped_somewhere += want_live < W * H ? 1 : 0;
    ++rounds;
    if (want_live == 0) break;
  }
  EXPECT_GE(rounds, 3);             // several rounds ran
  EXPECT_GE(stopped_somewhere, 2);  // and pixels stopped in them
}

// decides(): whether a decision is still to come. Never for fixed sampling (the CPU then keeps
// no sums of the odd samples, which only decisions read); for adaptive sampling until the round
// that ends at the maximum, with a decision after each round before it.
TEST(LivePixels, DecidesUntilTheLastRoundAndNeverForFixedSampling) {
  EXPECT_FALSE(LivePixels(AdaptiveSampling{false, 4, 4, 0.0f}, W, H, 1).decides());
  EXPECT_FALSE(LivePixels(AdaptiveSampling{true, 8, 8, 0.02f}, W, H, 1).decides());
  const AdaptiveSampling a{true, 2, 16, 0.0f};  // threshold 0: no pixel ever stops
  LivePixels live(a, W, H, 2);
  ImageRGBA sum(W, H), odd(W, H);
  int decisions = 0;
  for (int taken = 0; taken < a.maximum; taken = live.round_end()) {
    ASSERT_TRUE(live.decides()) << "taken " << taken;
    ASSERT_EQ(live.decide(live.round_end(), sum, odd), W * H);
    ++decisions;
  }
  EXPECT_FALSE(live.decides());
  EXPECT_EQ(live.round_end(), a.maximum);
  EXPECT_GE(decisions, 2);
}

}  // namespace
}  // namespace sdfreel
