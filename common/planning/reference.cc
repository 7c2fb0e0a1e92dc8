#include "common/planning/reference.h"

#include <algorithm>
#include <tuple>

namespace hexplore::planning {

double ReferenceSolution::max_length() const {
  double m = 0.0;
  for (const auto& r : routes) m = std::max(m, r.length_m);
  return m;
}

const ReferenceRoute* ReferenceSolution::route_of(const std::string& robot_id) const {
  for (const auto& r : routes)
    if (r.robot_id == robot_id) return &r;
  return nullptr;
}

std::optional<size_t> select_reference(const std::vector<ReferenceSolution>& solutions) {
  std::optional<size_t> best;
  for (size_t i = 0; i < solutions.size(); ++i) {
    if (!best) {
      best = i;
      continue;
    }
    const auto& a = solutions[i];
    const auto& b = solutions[*best];
    // Smaller max length first; then newer round (larger), then smaller source id.
    const auto ka = std::make_tuple(a.max_length(), ~a.round, a.source_robot);
    const auto kb = std::make_tuple(b.max_length(), ~b.round, b.source_robot);
    if (ka < kb) best = i;
  }
  return best;
}

bool reference_worth_sending(const std::vector<ReferenceSolution>& teammates, const ReferenceSolution& mine,
                             const std::optional<ReferenceSolution>& held) {
  std::vector<ReferenceSolution> candidates = teammates;
  const auto chosen_with = [&](const ReferenceSolution& own) {
    candidates.push_back(own);
    const bool chosen = select_reference(candidates) == candidates.size() - 1;
    candidates.pop_back();
    return chosen;
  };
  return chosen_with(mine) || (held && chosen_with(*held));
}

}  // namespace hexplore::planning
