#pragma once
// Planners by name. builtin() holds the full method ("hexplore"), the paper's ablations
// ("no-hetero", "no-cluster", "no-mnss", "no-assign") and its comparison baselines ("mdvrp+",
// "mromt+", "tspga+"); an unknown name is an error that lists the known ones.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/planning/planner.h"

namespace hexplore::planning {

class PlannerRegistry {
 public:
  using Factory = std::function<std::unique_ptr<Planner>()>;

  // Throws std::invalid_argument when the name is taken.
  void add(const std::string& name, Factory factory);
  // Throws std::invalid_argument: "unknown planner 'x'; known planners: a, b, ...".
  std::unique_ptr<Planner> create(const std::string& name) const;
  bool contains(const std::string& name) const { return factories_.count(name) != 0; }
  std::vector<std::string> names() const;

  static PlannerRegistry builtin();

 private:
  std::map<std::string, Factory> factories_;
};

}  // namespace hexplore::planning
