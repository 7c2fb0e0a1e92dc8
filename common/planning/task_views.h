#pragma once
// Task-view generation (paper "Task-View Generation"): for every facade-ISE supervoxel the
// best-scoring visible view from the traversable ground within the largest observation range,
// with its traversal and observation requirements; facade views also cover nearby ground-ISE
// supervoxels (composite views); the remaining traversable ground-ISE supervoxels get ground
// views standing on them. Every view is labelled public / private (labels.h).

#include <cstdint>
#include <optional>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "common/highlevel/high_level_map.h"
#include "common/planning/capabilities.h"
#include "common/planning/give_up_ledger.h"
#include "common/planning/ground_index.h"
#include "common/planning/visibility.h"

namespace hexplore::planning {

struct TaskView {
  uint64_t key = 0;            // the ISE supervoxel the view was made for (ordering, cluster ids)
  uint64_t ground_key = 0;     // ground supervoxel (topology vertex) the view stands on
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // p(xi) = p(ground supervoxel)
  Eigen::Vector3d look_at = Eigen::Vector3d::Zero();   // target centre (facade views)
  bool facade = false;         // in Xi_u (counts towards the observation time)
  // A ground view at the frontier of the known ground (frontier.h): reached only at its spot,
  // like a facade view, since what lies beyond the rim is seen from the rim.
  bool frontier = false;
  std::vector<uint64_t> targets;  // ISE supervoxels it observes: its own first, then composite ground ones
  int traversal_requirement = 1;
  int observation_requirement = 1;
  double score = 0.0;          // Vis of the best view (facade views)
  int label = -1;              // kPublic, species index, or kUnassignable
};

// What view generation made of one ISE supervoxel inside the exploration region.
enum class TargetOutcome : uint8_t {
  kView = 0,           // it has a task view (its own, or a composite facade view's)
  kGivenUp = 1,        // the team gave up on it (observed from its views, still incomplete)
  kNoViewpoint = 2,    // facade: no ground a robot reaches within range at a valid angle
  kOccluded = 3,       // facade: such ground exists, but every line of sight is blocked
  kUnreachable = 4,    // ground: no robot can stand on it
  kUnassignable = 5,   // its view's requirements match no species of the team
};
inline constexpr int kTargetOutcomeCount = 6;
const char* to_string(TargetOutcome o);

struct TargetRecord {
  uint64_t key = 0;
  TargetOutcome outcome = TargetOutcome::kView;
};

struct ViewGenerationStats {
  int facade_targets = 0;
  int facade_views = 0;
  int unobservable_facades = 0;
  int composite_ground = 0;
  int ground_views = 0;
  int frontier_views = 0;      // of the ground views, those at the frontier of the known ground (frontier.h)
  int outside_region = 0;      // ISE supervoxels outside the exploration region (no view)
  int ignored = 0;             // ISE supervoxels given up on (no view)
  int unreachable_ground = 0;  // ground ISE supervoxels nobody can stand on (no view)
  int public_views = 0;        // labelled c0 (every species may take them); the rest are private
  int64_t rays_cast = 0;
};

// The map-derived context shared by the planning stages of one round. `reachable` (when
// set) limits view positions to ground some robot of the team can drive to, so no view is
// made where nobody can stand (roofs, upper floors without stairs, closed-off pockets);
// `given_up` says which ISE supervoxels the team gave up on (observed from their views, still not
// covered); `region` bounds the coverage targets (TeamConfig::exploration_region).
struct MapContext {
  const highlevel::HighLevelMap& map;
  std::optional<std::unordered_set<uint64_t>> reachable;
  OcclusionGrid occlusion;
  GroundIndex ground;
  const GiveUpLedger* given_up = nullptr;
  // Per species index: the ground its robots can drive to (optional; RoundInputs::reachable).
  // With it, a view is chosen only where a species whose range suffices can stand.
  std::vector<std::unordered_set<uint64_t>> reachable_by_species;
  MapContext(const highlevel::HighLevelMap& m, const PlannerOptions& o,
             std::optional<std::unordered_set<uint64_t>> reachable_ground = std::nullopt,
             const GiveUpLedger* given_up_targets = nullptr)
      : map(m),
        reachable(std::move(reachable_ground)),
        occlusion(m, o.eta_s_m),
        ground(m, std::max(2.0, o.eta_r_m), reachable ? &*reachable : nullptr),
        given_up(given_up_targets) {}
  MapContext(const MapContext&) = delete;
  MapContext& operator=(const MapContext&) = delete;
  bool is_ignored(uint64_t key) const {
    if (!given_up) return false;
    const highlevel::Supervoxel* sv = map.find(key);
    return given_up->given_up(key, sv ? sv->voxel_count : 0);
  }
  bool is_reachable(uint64_t ground_key) const { return !reachable || reachable->count(ground_key); }
  // The target stayed incomplete when observed from about this spot (GiveUpLedger::tried_from):
  // its next view stands elsewhere where another spot sees it. Where none does, the same spot
  // serves again and the ledger's attempts give the target up: a target dropped on one robot's
  // ledger alone would keep a view on its teammates' and could be assigned to no one who takes
  // it (the robots' ledgers share given-up targets, not the spots they tried).
  bool tried_from(uint64_t target, const Eigen::Vector3d& spot) const {
    return given_up && given_up->tried_from(target, spot);
  }
};

// Best visible view of one facade target from the given candidates; false when none sees it.
// `range` limits the view distance (the largest observation range, or one species' range).
// `sighted` (optional) is set when some candidate passed range and angles (so a false result
// means every line of sight was blocked). With `team`, a candidate no species can take is
// passed over for the next best one: no species both reaches that far (range) and can stand
// there (traversal level, and ctx.reachable_by_species when set) -- e.g. a view only the
// long-range species could take, on ground only the other species can drive to.
bool best_facade_view(const MapContext& ctx, const highlevel::Supervoxel& target,
                      const std::vector<const highlevel::Supervoxel*>& candidates, double range,
                      const PlannerOptions& o, TaskView& view, int64_t* rays = nullptr, bool* sighted = nullptr,
                      const TeamCapabilities* team = nullptr);

// All task views of the map, in ascending key order; unassignable views are dropped.
// `targets` (optional) receives what became of every ISE supervoxel inside the region.
std::vector<TaskView> generate_task_views(const MapContext& ctx, const TeamCapabilities& team,
                                          const PlannerOptions& o, ViewGenerationStats* stats = nullptr,
                                          std::vector<TargetRecord>* targets = nullptr);

}  // namespace hexplore::planning
