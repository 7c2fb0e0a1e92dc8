#include "common/planning/hungarian.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hexplore::planning {
namespace {

// The shortest-augmenting-path Hungarian method with row and column potentials on an
// n x m matrix, n <= m (1-based internally). Returns the column of each row.
std::vector<int> solve_rows_le_columns(const std::vector<std::vector<double>>& a) {
  const int n = int(a.size());
  const int m = n == 0 ? 0 : int(a[0].size());
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(size_t(n) + 1, 0.0), v(size_t(m) + 1, 0.0);
  std::vector<int> p(size_t(m) + 1, 0), way(size_t(m) + 1, 0);  // p[j]: row matched to column j
  for (int i = 1; i <= n; ++i) {
    p[0] = i;
    int j0 = 0;
    std::vector<double> minv(size_t(m) + 1, inf);
    std::vector<char> used(size_t(m) + 1, 0);
    do {
      used[size_t(j0)] = 1;
      const int i0 = p[size_t(j0)];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= m; ++j) {
        if (used[size_t(j)]) continue;
        const double cur = a[size_t(i0 - 1)][size_t(j - 1)] - u[size_t(i0)] - v[size_t(j)];
        if (cur < minv[size_t(j)]) minv[size_t(j)] = cur, way[size_t(j)] = j0;
        if (minv[size_t(j)] < delta) delta = minv[size_t(j)], j1 = j;
      }
      for (int j = 0; j <= m; ++j) {
        if (used[size_t(j)]) {
          u[size_t(p[size_t(j)])] += delta;
          v[size_t(j)] -= delta;
        } else {
          minv[size_t(j)] -= delta;
        }
      }
      j0 = j1;
    } while (p[size_t(j0)] != 0);
    do {
      const int j1 = way[size_t(j0)];
      p[size_t(j0)] = p[size_t(j1)];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> column(size_t(n), -1);
  for (int j = 1; j <= m; ++j)
    if (p[size_t(j)] != 0) column[size_t(p[size_t(j)] - 1)] = j - 1;
  return column;
}

}  // namespace

Assignment hungarian(const std::vector<std::vector<double>>& costs) {
  Assignment out;
  const size_t rows = costs.size();
  out.column_of_row.assign(rows, -1);
  if (rows == 0) return out;
  const size_t cols = costs[0].size();
  for (const auto& row : costs)
    if (row.size() != cols) throw std::invalid_argument("hungarian: rows of different lengths");
  if (cols == 0) return out;

  // Forbidden pairs cost more than any difference between two assignments of allowed pairs,
  // so the optimum first uses as few of them as it can, then is cheapest among those.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& row : costs)
    for (double c : row)
      if (std::isfinite(c)) lo = std::min(lo, c), hi = std::max(hi, c);
  const size_t k = std::min(rows, cols);
  const double big = std::isfinite(lo) ? hi + double(k + 1) * (hi - lo + 1.0) : 1.0;

  const bool transpose = rows > cols;  // the method wants rows <= columns
  std::vector<std::vector<double>> a(transpose ? cols : rows, std::vector<double>(transpose ? rows : cols));
  for (size_t r = 0; r < rows; ++r)
    for (size_t c = 0; c < cols; ++c) {
      const double v = std::isfinite(costs[r][c]) ? costs[r][c] : big;
      (transpose ? a[c][r] : a[r][c]) = v;
    }
  const std::vector<int> match = solve_rows_le_columns(a);
  for (size_t i = 0; i < match.size(); ++i) {
    if (match[i] < 0) continue;
    const size_t r = transpose ? size_t(match[i]) : i;
    const size_t c = transpose ? i : size_t(match[i]);
    if (!std::isfinite(costs[r][c])) continue;  // only a forbidden pair was left for it
    out.column_of_row[r] = int(c);
    out.cost += costs[r][c];
    ++out.assigned;
  }
  return out;
}

}  // namespace hexplore::planning
