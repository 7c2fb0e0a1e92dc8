#pragma once
// How far two robots' plans of one round agree: the share of the clusters both plans hold that
// both give to the same robot (1: identical assignment; planners that cluster alike only).

#include "common/planning/planning_types.h"

namespace hexplore::planning {

double assignment_agreement(const PlanResult& a, const PlanResult& b);

}  // namespace hexplore::planning
