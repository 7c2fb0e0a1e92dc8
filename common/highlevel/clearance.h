#pragma once
// Body clearance on the high-level map: how far a ground point lies from what a body must not
// reach into, and where to move a path waypoint so that a body of a given radius fits there.
// Two kinds of obstacle patch:
// - facade supervoxels around body height (walls, rubble, vehicles). Facades are known only by
//   centre and normal, so each is a strip along the surface for wall-like ones, a disc for the
//   rest;
// - the rim of the known ground: a side of a ground supervoxel with no ground beyond it and no
//   wall in the way, a strip half a seed interval out. A body reaching past it hangs over space
//   the map has no ground in (the edge of a plateau or of the world, a hole, ground not seen
//   yet), and a body that cannot turn there is trapped on the edge: in the single-building
//   scene the MR1000 drove along the edge of the ground plane, could not turn round, and
//   shuttled there for 800 s of an 1800 s mission (common/highlevel/README.md).

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "common/highlevel/supervoxel.h"

namespace hexplore::highlevel {

struct ClearanceOptions {
  std::vector<double> body_radius_m;      // per species index (footprint half-diagonal); empty: off
  std::vector<double> body_half_width_m;  // per species index: the least clearance a body stands in
  double facade_half_extent_m = 0.5;  // a facade patch reaches this far from its centre (eta_s / 2)
  double ground_spacing_m = 1.0;      // ground supervoxels lie this far apart (eta_s): the rim test's step
  double ground_band_m = 1.0;         // ground this far above or below counts as the same level
  double below_m = 0.2;               // facades centred from this far below the ground ...
  double above_m = 1.5;               // ... to this far above it are in a body's way there,
  // except a facade facing down and higher than every body that may stand on the ground
  // (overhead_m): per species index, the body's height and traversal level; empty: none is.
  std::vector<double> body_height_m;
  std::vector<int> species_level;
  double max_shift_m = 0.5;           // a waypoint moves at most this far from its vertex

  bool enabled() const { return !body_radius_m.empty(); }
  // Above this height over ground of traversal requirement `requirement`, a facade facing down
  // is a ceiling over every body that may stand there (the tallest of the species whose level
  // meets the requirement, all species for 0, and a margin).
  double overhead_m(int requirement) const;
};

// The four sides of a ground supervoxel the rim test looks at: +x, -x, +y, -y (bit i of
// ClearanceIndex::rim_sides is side i).
inline constexpr int kRimSideCount = 4;
Eigen::Vector2d rim_side_direction(int side);
// Ground of a single voxel (a slab edge grazed from below a flight's top): it holds no body and
// says nothing of what lies beyond it, so it closes no side of the ground next to it. A count
// of 0 is a map that does not count voxels (hand-made ones): not a sliver.
inline bool sliver_of_ground(const Supervoxel& sv) { return sv.ground() && sv.voxel_count == 1; }

// Footprint half-diagonal and half-width of every species of the team (species index order).
std::vector<double> body_radii(const core::TeamConfig& team);
std::vector<double> body_half_widths(const core::TeamConfig& team);
// Both, for the map of a team.
ClearanceOptions clearance_options(const core::TeamConfig& team);

// Supervoxel centres on a planar grid, for clearance queries and for finding the ground
// vertices near a changed facade.
class ClearanceIndex {
 public:
  explicit ClearanceIndex(ClearanceOptions options = {}, double cell_m = 1.0);
  void insert(const Supervoxel& sv);
  void erase(const Supervoxel& sv);
  void clear() {
    cells_.clear();
    rim_cache_.clear();
  }

  // Distance in the plane from p to the nearest obstacle patch (facade in p's height band, rim
  // of the ground at p's level), looked for within `search_m`; search_m when none is that close.
  double clearance(const Eigen::Vector3d& p, double search_m) const;
  // p moved (at most max_shift_m, same z) away from the patches closer than `radius`, when
  // that gains clearance; else p.
  Eigen::Vector3d clear_position(const Eigen::Vector3d& p, double radius) const;
  // Both at once: clearance within `search_m` and the cleared position for each radius (the
  // obstacle patches around p are gathered once).
  struct Measure {
    double clearance = 0.0;
    std::vector<Eigen::Vector3d> waypoints;  // per radius
  };
  // At a ground supervoxel: on sloped ground the steps of its slope are not obstacles
  // (slopes.h: a flight's risers), nor is a ceiling over every body that may stand there.
  Measure measure(const Supervoxel& ground, double search_m, const std::vector<double>& radii) const;
  // How far a change at p (a supervoxel that appeared, moved or went) can change clearances:
  // it may add or remove a rim patch up to ~1.9 spacings away, which reaches bodies around it.
  double influence_m() const;
  // How far a vertex's clearance is measured: the largest body radius and a margin (a vertex
  // with no patch that close reads this value).
  double search_m() const;
  // The sides of a ground supervoxel (bit i: rim_side_direction(i)) from one search: open ones,
  // with neither ground about one spacing out at its level nor a wall (where the known ground
  // ends), and walled ones, with a wall but no ground there. The supervoxel need not be in the
  // index.
  struct RimSides {
    uint8_t open = 0;
    uint8_t walled = 0;
  };
  RimSides rim_sides(const Supervoxel& ground) const;
  // Keys of ground supervoxels centred within `radius` (in the plane) of p.
  std::vector<uint64_t> ground_near(const Eigen::Vector3d& p, double radius) const;

  const ClearanceOptions& options() const { return options_; }

 private:
  struct Entry {
    uint64_t key = 0;
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    bool facade = false;
    int requirement = 0;  // ground: its traversal requirement
    bool sliver = false;  // sliver_of_ground
  };
  static Entry entry_of(const Supervoxel& sv);
  // Ground at p with nothing known of it: level, and open to every species.
  static Entry ground_at(const Eigen::Vector3d& p);
  uint64_t cell_key(const Eigen::Vector3d& p) const;
  template <typename F>
  void for_each_near(const Eigen::Vector3d& p, double radius, F&& f) const;
  // An obstacle in the plane: a strip (centre, unit direction along it, half length) or a disc.
  struct Patch {
    Eigen::Vector2d center = Eigen::Vector2d::Zero();
    Eigen::Vector2d along = Eigen::Vector2d::Zero();  // zero: a disc of radius `half`
    double half = 0.0;
  };
  static Eigen::Vector2d nearest_point(const Patch& patch, const Eigen::Vector2d& p);
  Patch facade_patch(const Entry& facade) const;
  // Whether a facade is in the way of bodies on `ground`: in its height band, not a ceiling over
  // them, not a step of its slope.
  bool in_the_way(const Entry& facade, const Entry& ground) const;
  // The patches that may lie within `radius` of `ground` (facades in its way, rims at its level).
  std::vector<Patch> patches_near(const Entry& ground, double radius) const;
  // Which sides ground beyond closes, and which a wall closes (bit i: side i).
  struct SideClosure {
    uint8_t by_ground = 0;
    uint8_t by_wall = 0;
  };
  SideClosure side_closure(const Entry& g) const;
  uint8_t open_sides(const Entry& g) const;
  // open_sides of an entry of the index, kept until an entry near it changes (rim_reach_m).
  uint8_t cached_open_sides(const Entry& g) const;
  // How far from a ground supervoxel an entry can close one of its sides: a ground neighbour
  // up to (1.75, 0.75) spacings out, a facade patch reaching within half a spacing of a rim
  // centre.
  double rim_reach_m() const;
  // Forgets the cached sides of the ground entries a change at p can open or close.
  void invalidate_rims_near(const Eigen::Vector3d& p);
  // The rim patches of ground entry g: a strip half a spacing out on each open side.
  void add_rims(const Entry& g, std::vector<Patch>& out) const;
  static double distance(const std::vector<Patch>& patches, const Eigen::Vector2d& p, double cap);
  double largest_radius() const;
  Eigen::Vector3d pushed_clear(const std::vector<Patch>& patches, const Eigen::Vector3d& p, double radius) const;

  ClearanceOptions options_;
  double cell_m_;
  std::unordered_map<uint64_t, std::vector<Entry>> cells_;
  // Every body measured near a change gathers the rims of all ground around it, and each rim
  // asks open_sides of its ground: without the cache that was 40 % of a multi-building
  // mission's CPU (perf, stop 43). Only entries of the index are cached; insert and erase keep
  // it exact, so answers are the same as computed afresh.
  mutable std::unordered_map<uint64_t, uint8_t> rim_cache_;
};

}  // namespace hexplore::highlevel
