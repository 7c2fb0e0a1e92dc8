#pragma once
// Why exploration is not finished: every ISE supervoxel of the fused map inside the
// exploration region, with what view generation made of it (a view, given up, no viewpoint,
// occluded, unreachable, unassignable) and what its voxels lack (core::CoverageGap). The
// station writes these at the end of a mission (open_targets.csv, the top-down picture) and
// `hexplore_station --diagnose` asks a live team for them.

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "common/core/coverage_gap.h"
#include "common/highlevel/high_level_map.h"
#include "common/planning/task_views.h"
#include "hexplore/v1/plan.pb.h"

namespace hexplore::planning {

struct OpenTarget {
  uint64_t key = 0;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  bool facade = false;
  int voxel_count = 0;
  int covered_voxels = 0;
  core::CoverageGap gap = core::CoverageGap::kNone;
  TargetOutcome outcome = TargetOutcome::kView;
  int attempts = 0;
};

// The open targets of one round's view generation, in key order. `attempts` (optional):
// per target, how often the robot observed from or gave up reaching one of its views.
std::vector<OpenTarget> open_targets(const highlevel::HighLevelMap& map, const std::vector<TargetRecord>& records,
                                     const std::unordered_map<uint64_t, int>* attempts = nullptr);

// Counts by outcome and by coverage gap (indices: the enums' values).
struct OpenTargetCounts {
  std::array<int, kTargetOutcomeCount> by_outcome{};
  std::array<int, core::kCoverageGapCount> by_gap{};
  int total = 0;
};
OpenTargetCounts count_open_targets(const std::vector<OpenTarget>& targets);

v1::OpenTargetsReport to_proto(const std::string& robot_id, double sim_time_s, uint64_t round,
                               const std::vector<OpenTarget>& targets);
// Unknown enum values (a newer peer) read as kView / kNone.
std::vector<OpenTarget> from_proto(const v1::OpenTargetsReport& report);

}  // namespace hexplore::planning
