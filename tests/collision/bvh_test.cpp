#include "collision/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

namespace weft {
namespace {

using PairList = std::vector<std::pair<int, int>>;

// Boxes with centres uniform in [0, 1]^3 (flattened to z = 0 when `flat`, like a cloth lying on
// the floor) and half-sizes uniform in [0, maxHalfSize].
std::vector<Aabb> randomBoxes(int count, std::mt19937& rng, double maxHalfSize, bool flat = false) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Aabb> boxes(count);
  for (Aabb& box : boxes) {
    const Vec3 centre(unit(rng), unit(rng), flat ? 0.0 : unit(rng));
    const Vec3 half(maxHalfSize * unit(rng), maxHalfSize * unit(rng), flat ? 0.0 : maxHalfSize * unit(rng));
    box.grow(centre - half);
    box.grow(centre + half);
  }
  return boxes;
}

PairList treePairs(const Bvh& a, const Bvh& b) {
  PairList pairs;
  a.overlappingPairs(b, [&](int i, int j) { pairs.emplace_back(i, j); });
  return pairs;
}

PairList selfPairs(const Bvh& tree) {
  PairList pairs;
  tree.selfOverlappingPairs([&](int i, int j) { pairs.emplace_back(i, j); });
  return pairs;
}

PairList bruteForcePairs(const std::vector<Aabb>& a, const std::vector<Aabb>& b) {
  PairList pairs;
  for (int i = 0; i < static_cast<int>(a.size()); ++i) {
    for (int j = 0; j < static_cast<int>(b.size()); ++j) {
      if (a[i].overlaps(b[j])) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

PairList bruteForceSelfPairs(const std::vector<Aabb>& boxes) {
  PairList pairs;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
    for (int j = i + 1; j < static_cast<int>(boxes.size()); ++j) {
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

// Sorted copy; fails the test when a pair was reported twice.
PairList sortedWithoutRepeats(PairList pairs) {
  std::sort(pairs.begin(), pairs.end());
  EXPECT_EQ(std::adjacent_find(pairs.begin(), pairs.end()), pairs.end()) << "a pair was reported twice";
  return pairs;
}

Bvh builtOver(const std::vector<Aabb>& boxes) {
  Bvh tree;
  tree.build(boxes);
  return tree;
}

TEST(Bvh, TreeAgainstTreeFindsExactlyTheOverlappingPairs) {
  std::mt19937 rng(11);
  for (int countA : {0, 1, 2, 5, 64, 700}) {
    for (int countB : {0, 1, 3, 300}) {
      const std::vector<Aabb> a = randomBoxes(countA, rng, 0.08);
      const std::vector<Aabb> b = randomBoxes(countB, rng, 0.05);
      const PairList found = sortedWithoutRepeats(treePairs(builtOver(a), builtOver(b)));
      EXPECT_EQ(found, bruteForcePairs(a, b)) << countA << " x " << countB << " boxes";
    }
  }
}

TEST(Bvh, BoxQueryFindsExactlyTheOverlappingLeaves) {
  std::mt19937 rng(5);
  std::size_t reported = 0;
  for (int count : {0, 1, 7, 900, 2000}) {
    const std::vector<Aabb> boxes = randomBoxes(count, rng, 0.04, count == 2000);
    const Bvh tree = builtOver(boxes);
    for (const Aabb& query : randomBoxes(40, rng, 0.1)) {
      std::vector<int> found;
      tree.overlapping(query, [&](int i) { found.push_back(i); });
      std::sort(found.begin(), found.end());
      std::vector<int> expected;
      for (int i = 0; i < count; ++i) {
        if (boxes[i].overlaps(query)) expected.push_back(i);
      }
      EXPECT_EQ(found, expected) << count << " boxes";
      reported += found.size();
    }
  }
  EXPECT_GT(reported, 100u);  // the queries met boxes
}

TEST(Bvh, SelfQueryFindsEachOverlappingPairOnceWithTheSmallerIdFirst) {
  std::mt19937 rng(12);
  for (int count : {0, 1, 2, 4, 5, 9, 100, 2000}) {
    for (bool flat : {false, true}) {
      const std::vector<Aabb> boxes = randomBoxes(count, rng, 0.03, flat);
      const PairList found = selfPairs(builtOver(boxes));
      for (const auto& [i, j] : found) EXPECT_LT(i, j);
      EXPECT_EQ(sortedWithoutRepeats(found), bruteForceSelfPairs(boxes)) << count << " boxes, flat " << flat;
    }
  }
}

TEST(Bvh, BoxesThatOnlyTouchOverlap) {
  std::vector<Aabb> boxes(3);
  boxes[0].grow(Vec3(0, 0, 0));
  boxes[0].grow(Vec3(1, 1, 1));
  boxes[1].grow(Vec3(1, 0, 0));  // shares the face x = 1
  boxes[1].grow(Vec3(2, 1, 1));
  boxes[2].grow(Vec3(2, 1, 1));  // a point: the far corner of box 1
  EXPECT_EQ(sortedWithoutRepeats(selfPairs(builtOver(boxes))), (PairList{{0, 1}, {1, 2}}));

  // A 5 x 5 x 5 block of unit cubes: each touches its neighbours by a face, an edge or a corner,
  // in every direction and on both sides of every split of the tree.
  std::vector<Aabb> cubes;
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      for (int k = 0; k < 5; ++k) {
        Aabb cube;
        cube.grow(Vec3(i, j, k));
        cube.grow(Vec3(i + 1, j + 1, k + 1));
        cubes.push_back(cube);
      }
    }
  }
  const PairList expected = bruteForceSelfPairs(cubes);
  // Per axis 5 equal + 8 adjacent ordered index pairs: (13^3 - 125) / 2 unordered pairs of cubes.
  EXPECT_EQ(expected.size(), 1036u);
  EXPECT_EQ(sortedWithoutRepeats(selfPairs(builtOver(cubes))), expected);
  // Tree against tree, both ways round, against the block shifted by one cube along x.
  std::vector<Aabb> shifted = cubes;
  for (Aabb& cube : shifted) {
    cube.lo.x() += 1.0;
    cube.hi.x() += 1.0;
  }
  EXPECT_EQ(sortedWithoutRepeats(treePairs(builtOver(cubes), builtOver(shifted))), bruteForcePairs(cubes, shifted));
  EXPECT_EQ(sortedWithoutRepeats(treePairs(builtOver(shifted), builtOver(cubes))), bruteForcePairs(shifted, cubes));
}

TEST(Bvh, IdenticalBoxesAllOverlap) {
  std::vector<Aabb> boxes(50);
  for (Aabb& box : boxes) {
    box.grow(Vec3(0, 0, 0));
    box.grow(Vec3(1, 2, 3));
  }
  const Bvh tree = builtOver(boxes);
  EXPECT_EQ(sortedWithoutRepeats(selfPairs(tree)).size(), 50u * 49u / 2u);
  EXPECT_EQ(sortedWithoutRepeats(treePairs(tree, tree)).size(), 50u * 50u);
}

TEST(Bvh, RefitAfterMovingTheBoxesMatchesAFreshBuild) {
  std::mt19937 rng(13);
  std::normal_distribution<double> step(0.0, 0.05);
  std::vector<Aabb> boxes = randomBoxes(1500, rng, 0.02);
  const std::vector<Aabb> other = randomBoxes(400, rng, 0.02);
  Bvh tree = builtOver(boxes);
  const Bvh otherTree = builtOver(other);
  for (int round = 0; round < 3; ++round) {
    for (Aabb& box : boxes) {
      const Vec3 move(step(rng), step(rng), step(rng));
      box.lo += move;
      box.hi += move;
      box.inflate(0.002);
    }
    tree.refit(boxes);
    const Bvh fresh = builtOver(boxes);
    EXPECT_EQ(tree.leafCount(), 1500);
    EXPECT_EQ(tree.bounds().lo, fresh.bounds().lo);
    EXPECT_EQ(tree.bounds().hi, fresh.bounds().hi);
    const PairList refitted = sortedWithoutRepeats(selfPairs(tree));
    EXPECT_EQ(refitted, sortedWithoutRepeats(selfPairs(fresh)));
    EXPECT_EQ(refitted, bruteForceSelfPairs(boxes));
    EXPECT_EQ(sortedWithoutRepeats(treePairs(tree, otherTree)), bruteForcePairs(boxes, other));
  }
}

TEST(Bvh, QueriesVisitPairsInTheSameOrderEveryTime) {
  std::mt19937 rng(14);
  const std::vector<Aabb> boxes = randomBoxes(800, rng, 0.04);
  const std::vector<Aabb> other = randomBoxes(300, rng, 0.04);
  const Bvh first = builtOver(boxes);
  // A tree that went through another build first must end up the same.
  Bvh second = builtOver(other);
  second.build(boxes);
  EXPECT_EQ(selfPairs(first), selfPairs(second));
  const Bvh otherTree = builtOver(other);
  EXPECT_EQ(treePairs(first, otherTree), treePairs(second, otherTree));
}

TEST(Bvh, BoundsCoverEveryBoxAndAnEmptyTreeReportsNothing) {
  std::mt19937 rng(15);
  const std::vector<Aabb> boxes = randomBoxes(37, rng, 0.1);
  Aabb expected;
  for (const Aabb& box : boxes) expected.grow(box);
  const Bvh tree = builtOver(boxes);
  EXPECT_EQ(tree.bounds().lo, expected.lo);
  EXPECT_EQ(tree.bounds().hi, expected.hi);

  const Bvh empty = builtOver({});
  EXPECT_TRUE(empty.empty());
  EXPECT_FALSE(empty.bounds().overlaps(tree.bounds()));
  EXPECT_TRUE(selfPairs(empty).empty());
  EXPECT_TRUE(treePairs(empty, tree).empty());
  EXPECT_TRUE(treePairs(tree, empty).empty());
}

}  // namespace
}  // namespace weft
