#include "common/planning/planner_registry.h"

#include <stdexcept>

#include "common/planning/hexplore_planner.h"
#include "common/planning/mdvrp_planner.h"
#include "common/planning/mromt_planner.h"
#include "common/planning/tspga_planner.h"

namespace hexplore::planning {

void PlannerRegistry::add(const std::string& name, Factory factory) {
  if (!factories_.emplace(name, std::move(factory)).second)
    throw std::invalid_argument("planner '" + name + "' is already registered");
}

std::unique_ptr<Planner> PlannerRegistry::create(const std::string& name) const {
  const auto it = factories_.find(name);
  if (it == factories_.end()) {
    std::string known;
    for (const auto& n : names()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown planner '" + name + "'; known planners: " + known);
  }
  return it->second();
}

std::vector<std::string> PlannerRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& [name, f] : factories_) out.push_back(name);
  return out;
}

PlannerRegistry PlannerRegistry::builtin() {
  PlannerRegistry r;
  const std::pair<const char*, Ablation> kinds[] = {{"hexplore", Ablation::kNone},
                                                     {"no-hetero", Ablation::kNoHetero},
                                                     {"no-cluster", Ablation::kNoCluster},
                                                     {"no-mnss", Ablation::kNoMnss},
                                                     {"no-assign", Ablation::kNoAssign}};
  for (const auto& [name, ablation] : kinds) {
    const Ablation a = ablation;
    r.add(name, [a] { return std::make_unique<HexplorePlanner>(a); });
  }
  // The paper's comparison baselines (BASELINES.md).
  r.add("mdvrp+", [] { return std::make_unique<MdvrpPlanner>(); });
  r.add("mromt+", [] { return std::make_unique<MromtPlanner>(); });
  r.add("tspga+", [] { return std::make_unique<TspgaPlanner>(); });
  return r;
}

}  // namespace hexplore::planning
