#pragma once
// Observations a robot makes on its way. A task view is only the spot the planner chose; any
// spot from which a target passes the visibility test J (within the species' range, incidence
// below gamma_th, elevation inside the band its fixed sensors cover, line of sight clear) is
// a view of it. When the robot keeps a target in view from one spot for the species'
// observation time (at least min_dwell_s) and the target is still incomplete a settle time
// later, that counts as an observation in the GiveUpLedger, like one made at a task view. So
// targets the coverage criterion cannot complete (a corner whose voxels face two ways, a
// ceiling only seen at 45 degrees) are given up as robots pass them, instead of each costing
// a dedicated visit; and ground a robot drove across counts as reached.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "common/highlevel/high_level_map.h"
#include "common/planning/capabilities.h"
#include "common/planning/give_up_ledger.h"

namespace hexplore::planning {

struct PassingOptions {
  double range_m = 10.0;             // the species' observation range
  double elevation_min_deg = -45.0;  // band its fixed (not gimbal-aimed) sensors cover
  double elevation_max_deg = 45.0;
  double dwell_s = 1.0;              // in view this long from one spot
  double settle_s = 2.0;             // then judged this much later (map lag)
  double spot_m = 1.5;               // moving farther starts a new spot (GiveUpRules::distinct_m)
  double ground_reach_m = 1.0;       // a ground target is reached within this distance
};

class PassingObserver {
 public:
  PassingObserver(PassingOptions passing, PlannerOptions planner);

  // One look around from `position` at sim time `now_s` (call about once a second).
  void step(double now_s, const Eigen::Vector3d& position, const highlevel::HighLevelMap& map, GiveUpLedger& ledger);

  int observations() const { return observations_; }  // judged so far

 private:
  struct Interval {
    Eigen::Vector3d spot;
    double since_s = 0.0;
    double last_s = 0.0;
    bool judged = false;
    bool started = false;
  };
  struct Pending {
    uint64_t key;
    Eigen::Vector3d spot;
    double due_s;
  };
  bool in_view(const highlevel::Supervoxel& sv, const Eigen::Vector3d& position,
               const class OcclusionGrid& occlusion) const;

  PassingOptions passing_;
  PlannerOptions planner_;
  std::unordered_map<uint64_t, Interval> seen_;
  std::vector<Pending> pending_;
  double last_step_s_ = -1.0;
  int observations_ = 0;
};

// The passing options of a species: its range, and the elevation band its fixed LiDARs cover.
PassingOptions passing_options(const SpeciesCapability& species, double min_elevation_deg, double max_elevation_deg,
                               double observation_time_s);

}  // namespace hexplore::planning
