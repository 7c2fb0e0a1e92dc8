#include "tests/support/plan_agreement.h"

#include <unordered_map>

namespace hexplore::planning {

double assignment_agreement(const PlanResult& a, const PlanResult& b) {
  std::unordered_map<uint64_t, size_t> owner;
  for (size_t r = 0; r < a.robots.size(); ++r)
    for (uint64_t id : a.robots[r].cluster_ids) owner[id] = r;
  int same = 0, common = 0;
  for (size_t r = 0; r < b.robots.size(); ++r)
    for (uint64_t id : b.robots[r].cluster_ids)
      if (auto it = owner.find(id); it != owner.end()) ++common, same += it->second == r;
  return common ? double(same) / common : 0.0;
}

}  // namespace hexplore::planning
