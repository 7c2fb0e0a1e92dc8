#include "common/planning/open_targets.h"

#include <algorithm>

namespace hexplore::planning {

std::vector<OpenTarget> open_targets(const highlevel::HighLevelMap& map, const std::vector<TargetRecord>& records,
                                     const std::unordered_map<uint64_t, int>* attempts) {
  std::vector<OpenTarget> out;
  out.reserve(records.size());
  for (const TargetRecord& r : records) {
    const highlevel::Supervoxel* sv = map.find(r.key);
    if (!sv) continue;
    OpenTarget t;
    t.key = r.key;
    t.center = sv->center;
    t.facade = sv->facade();
    t.voxel_count = sv->voxel_count;
    t.covered_voxels = sv->covered_voxels;
    t.gap = sv->gap;
    t.outcome = r.outcome;
    if (attempts)
      if (const auto it = attempts->find(r.key); it != attempts->end()) t.attempts = it->second;
    out.push_back(t);
  }
  std::sort(out.begin(), out.end(), [](const OpenTarget& a, const OpenTarget& b) { return a.key < b.key; });
  // A ground target seen by two facade views is recorded twice; keep one.
  out.erase(std::unique(out.begin(), out.end(), [](const OpenTarget& a, const OpenTarget& b) { return a.key == b.key; }),
            out.end());
  return out;
}

OpenTargetCounts count_open_targets(const std::vector<OpenTarget>& targets) {
  OpenTargetCounts c;
  for (const OpenTarget& t : targets) {
    ++c.by_outcome[size_t(t.outcome)];
    ++c.by_gap[size_t(t.gap)];
    ++c.total;
  }
  return c;
}

v1::OpenTargetsReport to_proto(const std::string& robot_id, double sim_time_s, uint64_t round,
                               const std::vector<OpenTarget>& targets) {
  v1::OpenTargetsReport r;
  r.set_robot_id(robot_id);
  r.set_sim_time_s(sim_time_s);
  r.set_round(round);
  r.mutable_targets()->Reserve(int(targets.size()));
  for (const OpenTarget& t : targets) {
    v1::OpenTarget* m = r.add_targets();
    m->set_key(t.key);
    m->mutable_center_m()->set_x(t.center.x());
    m->mutable_center_m()->set_y(t.center.y());
    m->mutable_center_m()->set_z(t.center.z());
    m->set_facade(t.facade);
    m->set_voxel_count(uint32_t(std::max(0, t.voxel_count)));
    m->set_covered_voxels(uint32_t(std::max(0, t.covered_voxels)));
    m->set_coverage_gap(static_cast<v1::CoverageGap>(t.gap));
    m->set_state(static_cast<v1::OpenTargetState>(t.outcome));
    m->set_attempts(uint32_t(std::max(0, t.attempts)));
  }
  return r;
}

std::vector<OpenTarget> from_proto(const v1::OpenTargetsReport& report) {
  std::vector<OpenTarget> out;
  out.reserve(size_t(report.targets_size()));
  for (const v1::OpenTarget& m : report.targets()) {
    OpenTarget t;
    t.key = m.key();
    t.center = {m.center_m().x(), m.center_m().y(), m.center_m().z()};
    t.facade = m.facade();
    t.voxel_count = int(m.voxel_count());
    t.covered_voxels = int(std::min(m.covered_voxels(), m.voxel_count()));
    t.gap = core::coverage_gap_from_wire(uint32_t(m.coverage_gap()));
    const auto state = uint32_t(m.state());
    t.outcome = state < uint32_t(kTargetOutcomeCount) ? TargetOutcome(state) : TargetOutcome::kView;
    t.attempts = int(m.attempts());
    out.push_back(t);
  }
  return out;
}

}  // namespace hexplore::planning
