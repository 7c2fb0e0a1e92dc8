// The Hungarian method against brute force on random instances, square and rectangular,
// with forbidden (+inf) pairs.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "common/planning/hungarian.h"
#include "common/core/rng.h"

namespace hexplore::planning {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Every partial injective map rows -> columns over allowed pairs: the most rows assigned,
// then the least cost.
std::pair<int, double> brute_force(const std::vector<std::vector<double>>& c) {
  const size_t rows = c.size(), cols = c.empty() ? 0 : c[0].size();
  std::vector<char> used(cols, 0);
  std::pair<int, double> best{0, 0.0};
  std::function<void(size_t, int, double)> go = [&](size_t r, int n, double cost) {
    if (r == rows) {
      if (n > best.first || (n == best.first && cost < best.second)) best = {n, cost};
      return;
    }
    go(r + 1, n, cost);  // row r unassigned
    for (size_t j = 0; j < cols; ++j)
      if (!used[j] && std::isfinite(c[r][j])) {
        used[j] = 1;
        go(r + 1, n + 1, cost + c[r][j]);
        used[j] = 0;
      }
  };
  go(0, 0, 0.0);
  return best;
}

TEST(Hungarian, OptimalAgainstBruteForce) {
  core::PlanRng rng(11);
  int cases = 0;
  for (int rows = 1; rows <= 6; ++rows)
    for (int cols = 1; cols <= 6; ++cols)
      for (int trial = 0; trial < 12; ++trial) {
        const double forbidden = trial < 4 ? 0.0 : 0.3;
        std::vector<std::vector<double>> c(static_cast<size_t>(rows), std::vector<double>(static_cast<size_t>(cols)));
        for (auto& row : c)
          for (double& x : row) x = rng.uniform() < forbidden ? kInf : double(rng.below(50)) + (trial % 2) * rng.uniform();
        const auto [n, cost] = brute_force(c);
        const Assignment a = hungarian(c);
        ASSERT_EQ(a.assigned, n) << rows << "x" << cols << " trial " << trial;
        EXPECT_NEAR(a.cost, cost, 1e-9) << rows << "x" << cols << " trial " << trial;
        // A valid matching: allowed pairs, no column twice, cost as reported.
        std::vector<char> taken(size_t(cols), 0);
        double sum = 0.0;
        for (int r = 0; r < rows; ++r) {
          const int j = a.column_of_row[size_t(r)];
          if (j < 0) continue;
          ASSERT_TRUE(std::isfinite(c[size_t(r)][size_t(j)]));
          ASSERT_FALSE(taken[size_t(j)]);
          taken[size_t(j)] = 1;
          sum += c[size_t(r)][size_t(j)];
        }
        EXPECT_NEAR(sum, a.cost, 1e-9);
        ++cases;
      }
  EXPECT_EQ(cases, 6 * 6 * 12);
}

TEST(Hungarian, EdgeCases) {
  EXPECT_EQ(hungarian({}).assigned, 0);
  const Assignment none = hungarian({{kInf, kInf}, {kInf, kInf}});
  EXPECT_EQ(none.assigned, 0);
  EXPECT_EQ(none.column_of_row, (std::vector<int>{-1, -1}));
  // Taking the cheap pair (0,0) would leave row 1 unassigned: the most rows come first.
  const Assignment both = hungarian({{1.0, 5.0}, {2.0, kInf}});
  EXPECT_EQ(both.column_of_row, (std::vector<int>{1, 0}));
  EXPECT_DOUBLE_EQ(both.cost, 7.0);
  EXPECT_THROW(hungarian({{1.0, 2.0}, {3.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace hexplore::planning
