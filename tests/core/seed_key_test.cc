#include <gtest/gtest.h>

#include <random>
#include <unordered_set>

#include "common/core/seed_key.h"

namespace hexplore::core {
namespace {

TEST(SeedKey, RoundTripsAndIsCollisionFree) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int32_t> coord(-100000, 100000);
  std::unordered_set<uint64_t> keys;
  for (int i = 0; i < 20000; ++i) {
    const GridCell c{coord(rng), coord(rng), coord(rng)};
    EXPECT_EQ(cell_of_key(seed_key(c)), c);
    keys.insert(seed_key(c));
  }
  EXPECT_GT(keys.size(), 19990u);  // only true duplicates of random cells may collide
}

TEST(SeedKey, CellOfUsesFloorForNegativeCoordinates) {
  EXPECT_EQ(cell_of({-0.1, 0.1, 1.99}, 1.0), (GridCell{-1, 0, 1}));
  EXPECT_EQ(cell_of({-1.0, -1.01, 2.0}, 1.0), (GridCell{-1, -2, 2}));
}

}  // namespace
}  // namespace hexplore::core
