#pragma once
// Which coverage targets the team has stopped making views for, and why. A target (ISE
// supervoxel) is given up once it stayed incomplete after a robot observed it from `views`
// distinct spots (by default one: a dwell at its task view, or the species' observation time
// in view on the way), or after `attempts` tries of any kind (observed, or skipped because the
// robot was blocked on the way). One look is enough because a second one rarely completes
// what the first left open: in the default team's 3,600 s missions the MR1000's look from a
// second spot completed 8 of 86 and 6 of 88 such targets, the SLUGCAT's 6 of 61 and 8 of 58,
// and the second looks, at targets scattered round the site, are what kept small-building's
// missions going for 1,700 s and more (960-1,210 s with one look, the same completeness;
// common/planning/README.md, "A mission that ends"). A given-up target comes back when its
// supervoxel has grown markedly since (new voxels: the neighbourhood changed, e.g. a door
// opened onto it), so giving up is never final.
// Given-up targets travel with the team solution, so every planner agrees on what is left;
// the ledger numbers its changes (revision) so that a message can carry only what changed
// since an earlier one (GiveUpSharing).

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace hexplore::planning {

struct GiveUpRules {
  int views = 1;               // distinct observation spots
  int attempts = 3;            // tries of any kind
  double distinct_m = 1.5;     // observation spots closer than this are one spot
  double regrowth_ratio = 1.25;  // a given-up target whose voxel count grew past this ratio comes back
};

class GiveUpLedger {
 public:
  explicit GiveUpLedger(GiveUpRules rules = {}) : rules_(rules) {}

  // The target stayed incomplete after being observed from `spot`; `voxels` is its current
  // voxel count. Returns true when this gives it up.
  bool observed(uint64_t key, const Eigen::Vector3d& spot, int voxels);
  // A try that did not observe it (the robot was blocked or stuck on the way).
  bool failed(uint64_t key, int voxels);
  // A teammate gave it up at this voxel count (the larger count wins, so it comes back later).
  void merge(uint64_t key, int voxels);

  // Whether the team no longer makes views for the target, given its current voxel count.
  bool given_up(uint64_t key, int current_voxels) const;
  size_t given_up_count() const { return given_up_.size(); }
  // Each change to the given-up set (a target given up here or by a teammate, or its voxel
  // count raised) takes the next revision; a merge that changes nothing takes none, so what a
  // teammate sends is not echoed back.
  uint64_t revision() const { return revision_; }
  // (key, voxel count when given up) of the targets changed after `revision`, by key;
  // given_up_since(0) is the whole set. `mine_only`: only those whose last change was this
  // robot's own decision, not a teammate's (merge).
  std::vector<std::pair<uint64_t, int>> given_up_since(uint64_t revision, bool mine_only = false) const;
  // The revision of this robot's latest own change (0: none yet).
  uint64_t own_revision() const { return own_revision_; }
  // Whether the target stayed incomplete after an observation from within `distinct_m` of
  // `spot`. A second look from there sees what the first saw (the data of the default team:
  // 97 % of such repeats left the target open), so the next view of it stands elsewhere.
  bool tried_from(uint64_t key, const Eigen::Vector3d& spot) const;
  // Tries so far (observed or failed) per target.
  int attempts(uint64_t key) const;
  std::unordered_map<uint64_t, int> attempt_counts() const;
  const GiveUpRules& rules() const { return rules_; }

 private:
  struct Record {
    std::vector<Eigen::Vector3d> spots;  // distinct observation spots
    int attempts = 0;
  };
  bool decide(uint64_t key, const Record& r, int voxels);
  bool near_a_spot(const Record& r, const Eigen::Vector3d& spot) const;  // within distinct_m of one of its spots
  void set_given_up(uint64_t key, int voxels, bool mine);

  struct GivenUp {
    int voxels = 0;         // the target's voxel count when given up
    uint64_t revision = 0;  // when this entry last changed
    bool mine = false;      // that change was this robot's decision
  };
  GiveUpRules rules_;
  std::unordered_map<uint64_t, Record> records_;
  std::unordered_map<uint64_t, GivenUp> given_up_;
  uint64_t revision_ = 0;
  uint64_t own_revision_ = 0;
};

}  // namespace hexplore::planning
