// colorOverlap: the share of colour two point sets have in common.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "symmetry_segmentation/symmetry/color_histogram.h"

namespace ss = symmetry_segmentation;

namespace {

ss::PointT colored(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  ss::PointT point;
  point.r = r;
  point.g = g;
  point.b = b;
  return point;
}

std::vector<int> range(int first, int last) {
  std::vector<int> indices;
  for (int i = first; i <= last; ++i) indices.push_back(i);
  return indices;
}

}  // namespace

// One print over two parts (the same three colours in other proportions) shares most of its
// colour; a plain red part and a plain blue one share none; shading of a few units stays in a bin.
TEST(ColorHistogram, OnePrintSharesItsPaletteTwoColoursShareNothing) {
  ss::Cloud cloud;
  const ss::PointT red = colored(200, 30, 30), yellow = colored(230, 200, 20), blue = colored(30, 60, 200);
  for (int i = 0; i < 60; ++i) cloud.push_back(i < 40 ? red : i < 50 ? yellow : blue);   // part a: 0..59
  for (int i = 0; i < 60; ++i) cloud.push_back(i < 20 ? red : i < 40 ? yellow : blue);   // part b: 60..119
  for (int i = 0; i < 60; ++i) cloud.push_back(blue);                                     // part c: 120..179
  for (int i = 0; i < 60; ++i) cloud.push_back(colored(201, 31, 30));                     // part d: 180..239
  const auto a = range(0, 59), b = range(60, 119), c = range(120, 179), d = range(180, 239), red_part = range(0, 39);
  // min(40, 20) + min(10, 20) + min(10, 20) of 60 each.
  EXPECT_NEAR(ss::colorOverlap(cloud, a, b), 40.0f / 60.0f, 1e-4f);
  EXPECT_NEAR(ss::colorOverlap(cloud, b, a), 40.0f / 60.0f, 1e-4f);
  EXPECT_NEAR(ss::colorOverlap(cloud, red_part, c), 0.0f, 1e-6f);
  EXPECT_NEAR(ss::colorOverlap(cloud, red_part, d), 1.0f, 1e-4f) << "nearly the same red";
  EXPECT_NEAR(ss::colorOverlap(cloud, c, c), 0.0f, 1e-6f) << "no points of its own";
}

// Shared points count for neither side: what each has apart is compared.
TEST(ColorHistogram, SharedPointsCountForNeither) {
  ss::Cloud cloud;
  for (int i = 0; i < 20; ++i) cloud.push_back(colored(200, 30, 30));
  for (int i = 0; i < 20; ++i) cloud.push_back(colored(30, 60, 200));
  for (int i = 0; i < 20; ++i) cloud.push_back(colored(30, 200, 60));
  // a: red and blue, b: blue and green; apart they are red and green.
  EXPECT_NEAR(ss::colorOverlap(cloud, range(0, 39), range(20, 59)), 0.0f, 1e-6f);
  EXPECT_NEAR(ss::colorOverlap(cloud, range(0, 39), range(0, 59)), 0.0f, 1e-6f) << "a has nothing apart";
}
