#include "common/planning/reference.h"

#include <algorithm>

#include <gtest/gtest.h>

namespace hexplore::planning {
namespace {

ReferenceSolution solution(const std::string& source, uint64_t round, std::vector<double> lengths) {
  ReferenceSolution s;
  s.source_robot = source;
  s.round = round;
  for (size_t i = 0; i < lengths.size(); ++i) s.routes.push_back({"r" + std::to_string(i), {}, {}, lengths[i]});
  return s;
}

TEST(Reference, MinMaxRuleIndependentOfOrder) {
  std::vector<ReferenceSolution> all = {solution("a", 3, {10, 40}), solution("b", 3, {30, 31}),
                                        solution("c", 2, {5, 50}), solution("d", 4, {31, 30})};
  // b and d tie on the longest route (31); d is newer.
  std::vector<std::string> picks;
  std::sort(all.begin(), all.end(), [](auto& x, auto& y) { return x.source_robot < y.source_robot; });
  do {
    picks.push_back(all[*select_reference(all)].source_robot);
  } while (std::next_permutation(all.begin(), all.end(),
                                 [](auto& x, auto& y) { return x.source_robot < y.source_robot; }));
  for (const auto& p : picks) EXPECT_EQ(p, "d");
  EXPECT_FALSE(select_reference({}).has_value());
}

TEST(Reference, ASolutionTravelsWhenTeammatesWouldChooseIt) {
  const std::vector<ReferenceSolution> teammates = {solution("b", 7, {30, 31}), solution("c", 5, {20, 40})};
  // Alone, a robot's solution is every teammate's choice.
  EXPECT_TRUE(reference_worth_sending({}, solution("a", 1, {50}), std::nullopt));
  // Shorter than b's longest route: chosen.
  EXPECT_TRUE(reference_worth_sending(teammates, solution("a", 9, {25, 29}), std::nullopt));
  // Longer, and nothing of a's held: every teammate keeps choosing b.
  EXPECT_FALSE(reference_worth_sending(teammates, solution("a", 9, {25, 35}), std::nullopt));
  EXPECT_FALSE(reference_worth_sending(teammates, solution("a", 9, {25, 35}), solution("a", 8, {40, 10})));
  // The teammates hold an older solution of a's that they choose: the new one must replace it.
  EXPECT_TRUE(reference_worth_sending(teammates, solution("a", 9, {25, 35}), solution("a", 8, {12, 10})));
}

}  // namespace
}  // namespace hexplore::planning
