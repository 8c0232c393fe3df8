#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "symmetry_segmentation/table_noise.h"

namespace ss = symmetry_segmentation;

namespace {

constexpr int kWidth = 120, kHeight = 100;
constexpr float kMargin = 0.01f;

/// Heights above the table of a camera frame: the table's noise grows from 3 mm in the bottom
/// row (near) to 15 mm in the top row (far).
std::vector<float> noisyTable(std::mt19937& random) {
  std::normal_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> heights(kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y) {
    const float sigma = 0.015f - 0.012f * static_cast<float>(y) / (kHeight - 1);
    for (int x = 0; x < kWidth; ++x) heights[y * kWidth + x] = sigma * unit(random);
  }
  return heights;
}

std::size_t countAboveMargin(const std::vector<float>& heights, int y0, int y1, int x0, int x1,
                             const std::vector<bool>* except = nullptr) {
  std::size_t count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const int i = y * kWidth + x;
      count += heights[i] > kMargin && !(except && (*except)[i]);
    }
  }
  return count;
}

}  // namespace

// The far table's pixels above the margin are its noise (four in five of them found); with them
// a sparse slab of "object" would join whatever stands there.
TEST(TableNoise, TheFarTablesNoiseAboveTheMarginIsTheTable) {
  std::mt19937 random(3);
  const std::vector<float> heights = noisyTable(random);
  const std::size_t far_above = countAboveMargin(heights, 0, 30, 0, kWidth);
  ASSERT_GT(far_above, 500u);  // the case: a quarter of the far pixels
  const std::vector<bool> noise = ss::tableNoisePixels(kWidth, kHeight, heights, kMargin, 3);
  EXPECT_LT(countAboveMargin(heights, 0, 30, 0, kWidth, &noise), far_above / 5);
}

// What stands above the table's noise stays: a board lying flat (1.3 cm: its pixels' window is
// on the board), a handle two pixels wide (8 cm: far out of the table's noise around it), the
// edges of a low box (2 cm: half the window is the table, but the pixels right around are the box).
TEST(TableNoise, ABoardLyingFlatAndAThinHandleAreNotNoise) {
  std::mt19937 random(4);
  std::vector<float> heights = noisyTable(random);
  std::normal_distribution<float> unit(0.0f, 1.0f);
  for (int y = 10; y < 40; ++y) {
    for (int x = 10; x < 50; ++x) heights[y * kWidth + x] = 0.013f + 0.002f * unit(random);  // the board
    for (int x = 80; x < 82; ++x) heights[y * kWidth + x] = 0.08f;                            // the handle
  }
  for (int y = 60; y < 80; ++y) {
    for (int x = 60; x < 90; ++x) heights[y * kWidth + x] = 0.02f + 0.002f * unit(random);  // the box
  }
  const std::vector<bool> noise = ss::tableNoisePixels(kWidth, kHeight, heights, kMargin, 3);
  std::size_t board = 0, board_noise = 0, handle_noise = 0;
  for (int y = 10; y < 40; ++y) {
    for (int x = 12; x < 48; ++x) {  // the board but its rim
      if (y < 12 || y >= 38) continue;
      board += heights[y * kWidth + x] > kMargin;
      board_noise += noise[y * kWidth + x];
    }
    for (int x = 80; x < 82; ++x) handle_noise += noise[y * kWidth + x];
  }
  EXPECT_GT(board, 800u);
  EXPECT_EQ(board_noise, 0u);
  EXPECT_EQ(handle_noise, 0u);
  std::size_t box_noise = 0;
  for (int y = 60; y < 80; ++y) {
    for (int x = 60; x < 90; ++x) box_noise += noise[y * kWidth + x];
  }
  EXPECT_LE(box_noise, 4u);  // at most its corners
}

// Pixels without a point count for nothing; a window mostly without points judges nothing.
TEST(TableNoise, WindowsMostlyWithoutPointsJudgeNothing) {
  std::vector<float> heights(kWidth * kHeight, std::numeric_limits<float>::quiet_NaN());
  heights[50 * kWidth + 50] = 0.012f;
  for (int x = 40; x < 47; ++x) heights[50 * kWidth + x] = 0.0f;
  const std::vector<bool> noise = ss::tableNoisePixels(kWidth, kHeight, heights, kMargin, 3);
  EXPECT_FALSE(noise[50 * kWidth + 50]);
  // Off, or given a grid of the wrong size, nothing is noise.
  std::mt19937 random(5);
  const std::vector<float> table = noisyTable(random);
  const std::vector<bool> off = ss::tableNoisePixels(kWidth, kHeight, table, kMargin, 0);
  EXPECT_EQ(std::count(off.begin(), off.end(), true), 0);
  const std::vector<bool> wrong = ss::tableNoisePixels(kWidth, kHeight + 1, table, kMargin, 3);
  EXPECT_EQ(std::count(wrong.begin(), wrong.end(), true), 0);
}
