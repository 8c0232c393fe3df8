// Specks of the table's noise carried by a segment go; the object's own low points stay.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "symmetry_segmentation/symmetry/table_specks.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

// The table z = 0, its normal scaled: heights are normalised.
const ss::PlaneCoefficients kTable(0.0f, 0.0f, 2.0f, 0.0f);
constexpr float kLink = 0.025f;         // 2.5 voxels of 1 cm
constexpr float kScrapHeight = 0.015f;  // object_size.min_top_height

ss::PointT at(float x, float y, float z) {
  ss::PointT p;
  p.x = x; p.y = y; p.z = z;
  return p;
}

/// Every pair of points within 5 cm (the cut's max_neighbour_distance), from both ends.
std::vector<std::vector<int>> neighboursWithin5cm(const ss::Cloud& cloud) {
  std::vector<std::vector<int>> neighbours(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    for (std::size_t j = 0; j < cloud.size(); ++j) {
      if (i != j && (cloud[i].getVector3fMap() - cloud[j].getVector3fMap()).norm() < 0.05f) {
        neighbours[i].push_back(static_cast<int>(j));
      }
    }
  }
  return neighbours;
}

std::vector<int> range(int from, int to) {
  std::vector<int> indices(to - from);
  std::iota(indices.begin(), indices.end(), from);
  return indices;
}

}  // namespace

TEST(TableSpecks, AChainOfSpecksLeavesTheObjectItsOwnFootStays) {
  // A 10 cm box from the table up (its lowest row 5 mm over the table, within the scrap
  // height but joined to the rest), then specks 1.2 cm over the table, 4 cm apart - the cut's
  // links chain them, a 2.5 cm piece link does not - from 4 cm to 40 cm off the box.
  ss::Cloud cloud;
  test_clouds::addBox(cloud, {0.0f, 0.0f, -0.005f}, {0.1f, 0.1f, 0.105f}, 0.01f);
  const int box_size = static_cast<int>(cloud.size());
  for (float x = 0.14f; x < 0.5f; x += 0.04f) cloud.push_back(at(x, 0.05f, 0.012f));
  const auto neighbours = neighboursWithin5cm(cloud);
  const std::vector<int> segment = range(0, static_cast<int>(cloud.size()));

  EXPECT_EQ(ss::withoutTableSpecks(cloud, neighbours, segment, kTable, kLink, kScrapHeight), range(0, box_size));
  // Links of 4 cm make the chain one piece with the box: nothing is a speck.
  EXPECT_EQ(ss::withoutTableSpecks(cloud, neighbours, segment, kTable, 0.045f, kScrapHeight), segment);
  // Specks as high as the box's lower rows are none.
  EXPECT_EQ(ss::withoutTableSpecks(cloud, neighbours, segment, kTable, kLink, 0.01f), segment);
}

TEST(TableSpecks, ALowSegmentComesBackWhole) {
  // A book lying flat (1 cm) and a speck beside it: nothing rises above the scrap height, so
  // nothing tells the book from the speck; the scrap test judges the segment as one.
  ss::Cloud cloud;
  for (float x = 0.0f; x < 0.2f; x += 0.01f) {
    for (float y = 0.0f; y < 0.15f; y += 0.01f) cloud.push_back(at(x, y, 0.01f));
  }
  cloud.push_back(at(0.24f, 0.05f, 0.012f));
  const std::vector<int> segment = range(0, static_cast<int>(cloud.size()));
  EXPECT_EQ(ss::withoutTableSpecks(cloud, neighboursWithin5cm(cloud), segment, kTable, kLink, kScrapHeight), segment);
}

TEST(TableSpecks, OnlyTheSegmentsOwnPointsJoinPieces) {
  // The speck's link to the box runs through a point of another segment (index 1): without it
  // the speck is its own piece and goes. A plane not oriented (zero normal) changes nothing.
  ss::Cloud cloud;
  cloud.push_back(at(0.0f, 0.0f, 0.03f));     // the object, high
  cloud.push_back(at(0.0f, 0.015f, 0.012f));  // another segment's point, 2.3 cm from both
  cloud.push_back(at(0.0f, 0.035f, 0.01f));   // a speck, 4 cm from the object
  const auto neighbours = neighboursWithin5cm(cloud);
  const std::vector<int> segment{0, 2};
  EXPECT_EQ(ss::withoutTableSpecks(cloud, neighbours, segment, kTable, kLink, kScrapHeight), std::vector<int>{0});
  EXPECT_EQ(ss::withoutTableSpecks(cloud, neighbours, {0, 1, 2}, kTable, kLink, kScrapHeight),
            (std::vector<int>{0, 1, 2}));
  const ss::TableTop unoriented(ss::PlaneCoefficients::Zero());
  EXPECT_EQ(ss::withoutTableSpecks(cloud, neighbours, segment, unoriented, kLink, kScrapHeight), segment);
}

TEST(TableSpecks, ALowPieceTheCallerKeepsStays) {
  // A box and, 4 cm off its side, a flat piece 1 cm high (a book the cut joined to the box): a
  // low piece, gone unless the caller keeps it (object_size keeps one that hides the table).
  ss::Cloud cloud;
  test_clouds::addBox(cloud, {0.0f, 0.0f, -0.005f}, {0.1f, 0.1f, 0.105f}, 0.01f);
  const int box_size = static_cast<int>(cloud.size());
  for (float x = 0.14f; x < 0.3f; x += 0.01f) {
    for (float y = 0.0f; y < 0.1f; y += 0.01f) cloud.push_back(at(x, y, 0.01f));
  }
  const auto neighbours = neighboursWithin5cm(cloud);
  const std::vector<int> segment = range(0, static_cast<int>(cloud.size()));
  EXPECT_EQ(ss::withoutTableSpecks(cloud, neighbours, segment, kTable, kLink, kScrapHeight), range(0, box_size));
  std::size_t asked = 0;
  const auto keep_flat_pieces = [&](const std::vector<int>& piece) {
    ++asked;
    return piece.size() > 100;
  };
  EXPECT_EQ(ss::withoutTableSpecks(cloud, neighbours, segment, kTable, kLink, kScrapHeight, keep_flat_pieces), segment);
  EXPECT_EQ(asked, 1u) << "asked once per low piece";
}

TEST(TableSpecks, HeightsAreOverTheTablesFittedTopWhereItBendsAwayFromItsPlane) {
  // A table rising by 0.1 x^2 (2 cm at x = 0.45, a far table bending away) and specks 1 cm over
  // it there: over the plane they stand 1.9-3.1 cm high, above the scrap height, and stay; over
  // the table's fitted top they are 1 cm high and go.
  const auto surface = test_clouds::bendingTableTop(0.1f);
  ASSERT_TRUE(surface);
  ss::Cloud cloud;
  test_clouds::addBox(cloud, {-0.05f, -0.05f, 0.0f}, {0.05f, 0.05f, 0.1f}, 0.01f);
  const int box_size = static_cast<int>(cloud.size());
  for (float x = 0.3f; x < 0.48f; x += 0.04f) cloud.push_back(at(x, 0.0f, 0.1f * x * x + 0.01f));
  const auto neighbours = neighboursWithin5cm(cloud);
  const std::vector<int> segment = range(0, static_cast<int>(cloud.size()));
  EXPECT_EQ(ss::withoutTableSpecks(cloud, neighbours, segment, kTable, kLink, kScrapHeight), segment);
  EXPECT_EQ(ss::withoutTableSpecks(cloud, neighbours, segment, ss::TableTop(kTable, surface), kLink, kScrapHeight),
            range(0, box_size));
}
