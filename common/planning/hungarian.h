#pragma once
// Minimum-cost assignment of rows to columns (Kuhn–Munkres with potentials, O(n^2 m) for
// n rows <= m columns, O(n^3) square): MROMT+'s robot <-> cluster matching. Rectangular
// inputs are fine; +inf marks a forbidden pair, and a row whose every column is forbidden
// (or that loses the competition for the allowed ones) stays unassigned.

#include <vector>

namespace hexplore::planning {

struct Assignment {
  std::vector<int> column_of_row;  // -1: unassigned
  double cost = 0.0;               // sum over assigned pairs
  int assigned = 0;
};

// costs[r][c]; every row must have the same number of columns. Among all assignments that
// assign the most rows (allowed pairs only), returns one of least total cost. Ties between
// equally cheap assignments are decided by the input order alone (deterministic).
Assignment hungarian(const std::vector<std::vector<double>>& costs);

}  // namespace hexplore::planning
