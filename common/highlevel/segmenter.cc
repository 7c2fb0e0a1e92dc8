#include "common/highlevel/segmenter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>


namespace hexplore::highlevel {
namespace {

// Key offsets of the 26 neighbours in the seed_key packing (x lowest).
std::array<int64_t, 26> neighbour_deltas() {
  std::array<int64_t, 26> d{};
  int n = 0;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (dx != 0 || dy != 0 || dz != 0) d[n++] = dx + dy * (int64_t{1} << core::kSeedKeyAxisBits) + dz * (int64_t{1} << 2 * core::kSeedKeyAxisBits);
  return d;
}
const std::array<int64_t, 26> kNeighbours = neighbour_deltas();

uint64_t shifted(uint64_t key, int64_t delta) { return static_cast<uint64_t>(static_cast<int64_t>(key) + delta); }

int64_t sq(int64_t v) { return v * v; }

// The class bits of the supervoxels a voxel may join (supervoxel.h): traversable ground, or
// facade of the voxel's facing.
uint64_t class_bits(const VoxelSample& v) {
  if (v.traversable_ground()) return 0;
  return supervoxel_key({0, 0, 0}, SurfaceClass::kFacade, facing_of(v.normal)) & kClassKeyMask;
}

// Every class a seed cell may hold.
std::array<uint64_t, 1 + kFacingCount> all_classes() {
  std::array<uint64_t, 1 + kFacingCount> out{};
  out[0] = 0;
  for (int f = 0; f < kFacingCount; ++f)
    out[1 + f] = supervoxel_key({0, 0, 0}, SurfaceClass::kFacade, Facing(f)) & kClassKeyMask;
  return out;
}
const std::array<uint64_t, 1 + kFacingCount> kClasses = all_classes();

int64_t cell_dist2(const core::GridCell& a, const core::GridCell& b) {
  return sq(int64_t{a.x} - b.x) + sq(int64_t{a.y} - b.y) + sq(int64_t{a.z} - b.z);
}

}  // namespace

SupervoxelSegmenter::SupervoxelSegmenter(SegmenterParams params, std::vector<int> species_levels)
    : params_(params), levels_(std::move(species_levels)) {
  params_.validate();
  if (levels_.empty()) throw std::invalid_argument("SupervoxelSegmenter: at least one species level is needed");
  hops_ = params_.max_hops > 0
              ? params_.max_hops
              : std::max(1, static_cast<int>(std::floor(0.75 * params_.eta_s_m / params_.resolution_m)));
}

const Supervoxel* SupervoxelSegmenter::find(uint64_t key) const {
  auto it = supervoxels_.find(key);
  return it == supervoxels_.end() ? nullptr : &it->second;
}

std::vector<EdgeKey> SupervoxelSegmenter::edges() const {
  std::vector<EdgeKey> out;
  out.reserve(edge_count_);
  for (const auto& [a, ns] : adjacency_)
    for (uint64_t b : ns)
      if (a < b) out.push_back({a, b});
  std::sort(out.begin(), out.end());
  return out;
}

uint64_t SupervoxelSegmenter::supervoxel_of(const core::GridCell& voxel) const {
  const VoxelRec* rec = voxels_.find(voxel_key(voxel));
  if (rec == nullptr || rec->label == 0) return 0;
  return group_of_seed(rec->label);
}

uint64_t SupervoxelSegmenter::group_of_seed(uint64_t seed) const {
  auto it = seed_group_.find(seed);
  return it == seed_group_.end() ? 0 : it->second;
}

// Cell membership uses the voxel centre so every robot puts a voxel in the same cell.
uint64_t SupervoxelSegmenter::seed_cell_of_voxel(const core::GridCell& c, uint64_t cls) const {
  const Eigen::Vector3d centre((c.x + 0.5) * params_.resolution_m, (c.y + 0.5) * params_.resolution_m,
                               (c.z + 0.5) * params_.resolution_m);
  return core::seed_key(core::cell_of(centre, params_.eta_s_m)) | cls;
}

Eigen::Vector3d SupervoxelSegmenter::voxel_center(uint64_t vkey) const {
  const core::GridCell c = core::cell_of_key(vkey);
  return Eigen::Vector3d(c.x + 0.5, c.y + 0.5, c.z + 0.5) * params_.resolution_m;
}

Eigen::Vector3d SupervoxelSegmenter::centroid(const Seed& s) const {
  const double n = static_cast<double>(s.cell_voxels.size());
  return Eigen::Vector3d(s.key_sum[0] / n + 0.5, s.key_sum[1] / n + 0.5, s.key_sum[2] / n + 0.5) *
         params_.resolution_m;
}

void SupervoxelSegmenter::remove_voxel(uint64_t vkey, std::unordered_set<uint64_t>& dirty_seeds) {
  const VoxelRec rec = *voxels_.find(vkey);
  Seed& cell = seeds_[rec.seed_cell];
  cell.cell_voxels.erase(vkey);
  cell.key_sum[0] -= rec.sample.key.x;
  cell.key_sum[1] -= rec.sample.key.y;
  cell.key_sum[2] -= rec.sample.key.z;
  dirty_seeds.insert(rec.seed_cell);
  if (rec.label != 0) {
    Seed& owner = seeds_[rec.label];
    owner.region.erase(vkey);
    owner.stats.add(rec.sample, -1, levels_.size());
    touched_seeds_.insert(rec.label);
    reshaped_groups_.insert(group_of_seed(rec.label));
  }
  voxels_.erase(vkey);
}

void SupervoxelSegmenter::insert_voxel(const VoxelSample& v, std::unordered_set<uint64_t>& dirty_seeds) {
  const uint64_t vkey = voxel_key(v.key);
  VoxelRec rec;
  rec.sample = v;
  rec.cls = class_bits(v);
  rec.seed_cell = seed_cell_of_voxel(v.key, rec.cls);
  Seed& cell = seeds_[rec.seed_cell];
  cell.cell_voxels.insert(vkey);
  cell.key_sum[0] += v.key.x;
  cell.key_sum[1] += v.key.y;
  cell.key_sum[2] += v.key.z;
  dirty_seeds.insert(rec.seed_cell);
  voxels_.insert(vkey) = rec;
}

// Picks each dirty cell's seed voxel: the voxel nearest the centroid of the cell's voxels
// (exact integer comparison; ties go to the smaller key).
std::unordered_set<uint64_t> SupervoxelSegmenter::refresh_seeds(const std::unordered_set<uint64_t>& dirty_seeds) {
  for (uint64_t skey : dirty_seeds) {
    Seed& s = seeds_[skey];
    if (s.cell_voxels.empty()) {
      s.seed_voxel = 0;
      continue;
    }
    const int64_t n = static_cast<int64_t>(s.cell_voxels.size());
    __int128 best = -1;
    uint64_t best_key = 0;
    for (uint64_t vkey : s.cell_voxels) {
      const core::GridCell c = core::cell_of_key(vkey);
      const __int128 dx = static_cast<__int128>(n) * c.x - s.key_sum[0];
      const __int128 dy = static_cast<__int128>(n) * c.y - s.key_sum[1];
      const __int128 dz = static_cast<__int128>(n) * c.z - s.key_sum[2];
      const __int128 d = dx * dx + dy * dy + dz * dz;
      if (best < 0 || d < best || (d == best && vkey < best_key)) {
        best = d;
        best_key = vkey;
      }
    }
    s.seed_voxel = best_key;
  }
  return dirty_seeds;
}

// Recomputes the merge groups (connected components of "adjacent cell, same class, centroids
// within eta_e") around the changed seeds. A group's key is its smallest seed key.
void SupervoxelSegmenter::regroup(const std::unordered_set<uint64_t>& changed_seeds) {
  std::vector<uint64_t> work;
  std::unordered_set<uint64_t> pending;
  auto dissolve = [&](uint64_t group) {
    if (!dissolved_groups_.insert(group).second) return;
    auto it = groups_.find(group);
    if (it == groups_.end()) return;
    for (uint64_t m : it->second) {
      if (pending.insert(m).second) work.push_back(m);
      seed_group_.erase(m);
    }
    groups_.erase(it);
  };
  for (uint64_t s : changed_seeds) {
    auto g = seed_group_.find(s);
    if (g != seed_group_.end()) dissolve(g->second);
    if (pending.insert(s).second) work.push_back(s);
  }
  std::unordered_set<uint64_t> done;
  for (size_t w = 0; w < work.size(); ++w) {
    const uint64_t start = work[w];
    if (done.count(start) != 0) continue;
    auto sit = seeds_.find(start);
    if (sit == seeds_.end() || sit->second.cell_voxels.empty()) continue;
    std::vector<uint64_t> component{start};
    done.insert(start);
    for (size_t i = 0; i < component.size(); ++i) {
      const uint64_t s = component[i];
      const uint64_t cls = s & kClassKeyMask;
      const core::GridCell c = seed_cell_of(s);
      const Eigen::Vector3d cs = centroid(seeds_.at(s));
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            if (dx == 0 && dy == 0 && dz == 0) continue;
            const uint64_t t = core::seed_key({c.x + dx, c.y + dy, c.z + dz}) | cls;
            if (done.count(t) != 0) continue;
            auto tit = seeds_.find(t);
            if (tit == seeds_.end() || tit->second.cell_voxels.empty()) continue;
            if ((centroid(tit->second) - cs).norm() > params_.eta_e_m) continue;
            auto g = seed_group_.find(t);
            if (g != seed_group_.end()) dissolve(g->second);
            done.insert(t);
            component.push_back(t);
          }
    }
    const uint64_t key = *std::min_element(component.begin(), component.end());
    for (uint64_t m : component) seed_group_[m] = key;
    reshaped_groups_.insert(key);
    groups_[key] = std::move(component);
  }
}

void SupervoxelSegmenter::set_label(uint64_t vkey, VoxelRec& rec, uint64_t label) {
  if (rec.label != 0) {
    Seed& old = seeds_.at(rec.label);
    old.region.erase(vkey);
    old.stats.add(rec.sample, -1, levels_.size());
    touched_seeds_.insert(rec.label);
    reshaped_groups_.insert(group_of_seed(rec.label));
  }
  rec.label = label;
  Seed& now = seeds_.at(label);
  now.region.insert(vkey);
  now.stats.add(rec.sample, +1, levels_.size());
  touched_seeds_.insert(label);
  reshaped_groups_.insert(group_of_seed(label));
}

// Wavefront propagation from every seed near the dirty cells, level by level over the 26-
// neighbourhood of same-class voxels, at most hops_ levels. A voxel reached at level L takes,
// among its level L-1 neighbours' seeds, the one whose seed voxel is nearest (then smaller
// key): a function of the voxels within hops_ of it, so re-growing the dirty cells plus one
// cell of margin (hops_ * resolution <= eta_s) gives exactly what a full re-segmentation would.
size_t SupervoxelSegmenter::relabel(const std::unordered_set<uint64_t>& dirty_seeds) {
  std::unordered_set<uint64_t> d0;
  for (uint64_t s : dirty_seeds) d0.insert(core::seed_key(seed_cell_of(s)));
  auto dilate = [](const std::unordered_set<uint64_t>& in) {
    std::unordered_set<uint64_t> out;
    out.reserve(in.size() * 9);
    for (uint64_t k : in) {
      out.insert(k);
      for (int64_t d : kNeighbours) out.insert(shifted(k, d));
    }
    return out;
  };
  const auto d1 = dilate(d0);
  const auto d2 = dilate(d1);

  // Wavefront state lives in the voxel records, tagged with a fresh stamp per propagation.
  const uint32_t stamp = ++stamp_;
  std::unordered_map<uint64_t, core::GridCell> seed_voxel_cell;  // label -> seed voxel key
  std::vector<uint64_t> frontier;
  for (uint64_t cell : d2) {
    const core::GridCell c = core::cell_of_key(cell);
    for (uint64_t cls : kClasses) {
      const uint64_t skey = core::seed_key(c) | cls;
      auto it = seeds_.find(skey);
      if (it == seeds_.end() || it->second.cell_voxels.empty()) continue;
      VoxelRec* rec = voxels_.find(it->second.seed_voxel);
      rec->visit_stamp = stamp;
      rec->wave_label = skey;
      seed_voxel_cell.emplace(skey, core::cell_of_key(it->second.seed_voxel));
      frontier.push_back(it->second.seed_voxel);
    }
  }
  std::vector<uint64_t> next;
  for (int level = 1; level <= hops_ && !frontier.empty(); ++level) {
    next.clear();
    for (uint64_t u : frontier) {
      const VoxelRec* from = voxels_.find(u);
      const uint64_t label = from->wave_label;
      const uint64_t cls = from->cls;
      for (int64_t d : kNeighbours) {
        const uint64_t n = shifted(u, d);
        VoxelRec* rec = voxels_.find(n);
        if (rec == nullptr || rec->visit_stamp == stamp || rec->cls != cls) continue;
        if (rec->candidate_stamp != stamp) {
          rec->candidate_stamp = stamp;
          rec->candidate_label = label;
          next.push_back(n);
          continue;
        }
        if (rec->candidate_label == label) continue;
        const core::GridCell nc = core::cell_of_key(n);
        const int64_t mine = cell_dist2(nc, seed_voxel_cell.at(label));
        const int64_t theirs = cell_dist2(nc, seed_voxel_cell.at(rec->candidate_label));
        if (mine < theirs || (mine == theirs && label < rec->candidate_label)) rec->candidate_label = label;
      }
    }
    for (uint64_t n : next) {
      VoxelRec* rec = voxels_.find(n);
      rec->visit_stamp = stamp;
      rec->wave_label = rec->candidate_label;
    }
    frontier.swap(next);
  }

  size_t examined = 0;
  for (uint64_t cell : d1) {
    const core::GridCell c = core::cell_of_key(cell);
    for (uint64_t cls : kClasses) {
      const uint64_t skey = core::seed_key(c) | cls;
      auto it = seeds_.find(skey);
      if (it == seeds_.end()) continue;
      for (uint64_t vkey : it->second.cell_voxels) {
        VoxelRec& rec = *voxels_.find(vkey);
        const uint64_t label = rec.visit_stamp == stamp ? rec.wave_label : skey;
        if (rec.label != label) set_label(vkey, rec, label);
        ++examined;
      }
    }
  }
  return examined;
}

Supervoxel SupervoxelSegmenter::aggregate(uint64_t group) const {
  VoxelSetStats total;
  for (uint64_t s : groups_.at(group)) total.add(seeds_.at(s).stats);
  // The patch search walks the voxels; a fully covered group needs none.
  const bool open_patch = total.count > 0 && total.covered != total.count && has_ise_patch(group);
  return supervoxel_from(group, total, open_patch, levels_);
}

bool SupervoxelSegmenter::has_ise_patch(uint64_t group) const {
  const size_t wanted = static_cast<size_t>(params_.min_ise_patch_voxels);
  auto open_member = [&](uint64_t vkey) {
    const VoxelRec* rec = voxels_.find(vkey);
    return rec != nullptr && !rec->sample.covered() && rec->label != 0 && group_of_seed(rec->label) == group;
  };
  std::unordered_set<uint64_t> seen;
  std::vector<uint64_t> stack;
  for (uint64_t s : groups_.at(group)) {
    for (uint64_t start : seeds_.at(s).region) {
      if (!open_member(start) || !seen.insert(start).second) continue;
      size_t patch = 0;
      stack.assign(1, start);
      while (!stack.empty()) {
        const uint64_t v = stack.back();
        stack.pop_back();
        if (++patch >= wanted) return true;
        for (int64_t d : kNeighbours) {
          const uint64_t n = shifted(v, d);
          if (open_member(n) && seen.insert(n).second) stack.push_back(n);
        }
      }
    }
  }
  return false;
}

std::unordered_set<uint64_t> SupervoxelSegmenter::ground_neighbours(uint64_t group) const {
  std::unordered_set<uint64_t> out;
  for (uint64_t s : groups_.at(group)) {
    for (uint64_t v : seeds_.at(s).region) {
      for (int64_t d : kNeighbours) {
        const VoxelRec* rec = voxels_.find(shifted(v, d));
        if (rec == nullptr || rec->cls != 0 || rec->label == 0) continue;
        const uint64_t g = group_of_seed(rec->label);
        if (g != group && g != 0) out.insert(g);
      }
    }
  }
  return out;
}

SegmentationChange SupervoxelSegmenter::update(std::span<const VoxelSample> voxels) {
  touched_seeds_.clear();
  reshaped_groups_.clear();
  dissolved_groups_.clear();
  std::unordered_set<uint64_t> dirty;

  for (const VoxelSample& v : voxels) {
    const uint64_t vkey = voxel_key(v.key);
    VoxelRec* found = voxels_.find(vkey);
    if (v.removed()) {
      if (found != nullptr) remove_voxel(vkey, dirty);
      continue;
    }
    if (found != nullptr) {
      VoxelRec& rec = *found;
      if (rec.cls == class_bits(v)) {  // same class: attributes only
        if (rec.label != 0) {
          VoxelSetStats& st = seeds_.at(rec.label).stats;
          st.add(rec.sample, -1, levels_.size());
          st.add(v, +1, levels_.size());
          touched_seeds_.insert(rec.label);
        }
        rec.sample = v;
        continue;
      }
      remove_voxel(vkey, dirty);
    }
    insert_voxel(v, dirty);
  }

  SegmentationChange change;
  if (!dirty.empty()) {
    const auto changed = refresh_seeds(dirty);
    regroup(changed);
    change.relabelled_voxels = relabel(dirty);
    for (uint64_t s : dirty) {
      auto it = seeds_.find(s);
      if (it != seeds_.end() && it->second.cell_voxels.empty() && it->second.region.empty()) seeds_.erase(it);
    }
  }

  // Groups whose attributes must be recomputed.
  std::set<uint64_t> recompute;
  for (uint64_t s : touched_seeds_) {
    const uint64_t g = group_of_seed(s);
    if (g != 0) recompute.insert(g);
  }
  for (uint64_t g : reshaped_groups_) {
    if (groups_.count(g) != 0) recompute.insert(g);
  }

  std::set<EdgeKey> added;
  std::set<EdgeKey> removed;
  auto drop_edge = [&](uint64_t a, uint64_t b) {
    adjacency_[a].erase(b);
    adjacency_[b].erase(a);
    const EdgeKey e = EdgeKey::of(a, b);
    if (added.erase(e) == 0) removed.insert(e);
  };
  for (uint64_t g : dissolved_groups_) {
    if (groups_.count(g) != 0) continue;
    if (supervoxels_.erase(g) != 0) change.removed.push_back(g);
    auto it = adjacency_.find(g);
    if (it == adjacency_.end()) continue;
    const std::vector<uint64_t> partners(it->second.begin(), it->second.end());
    for (uint64_t h : partners) drop_edge(g, h);
    adjacency_.erase(g);
  }
  for (uint64_t g : recompute) {
    Supervoxel sv = aggregate(g);
    auto [it, inserted] = supervoxels_.try_emplace(g, sv);
    if (inserted || !(it->second == sv)) {
      it->second = sv;
      change.upserted.push_back(g);
    }
  }
  for (uint64_t g : reshaped_groups_) {
    if (groups_.count(g) == 0 || surface_of_key(g) != SurfaceClass::kGround) continue;
    const auto now = ground_neighbours(g);
    auto& old = adjacency_[g];
    std::vector<uint64_t> gone;
    for (uint64_t h : old)
      if (now.count(h) == 0) gone.push_back(h);
    for (uint64_t h : gone) drop_edge(g, h);
    for (uint64_t h : now) {
      if (adjacency_[g].insert(h).second) {
        adjacency_[h].insert(g);
        const EdgeKey e = EdgeKey::of(g, h);
        if (removed.erase(e) == 0) added.insert(e);
      }
    }
    if (adjacency_[g].empty()) adjacency_.erase(g);
  }
  edge_count_ = edge_count_ + added.size() - removed.size();
  change.edges_added.assign(added.begin(), added.end());
  change.edges_removed.assign(removed.begin(), removed.end());
  std::sort(change.removed.begin(), change.removed.end());
  return change;
}

SegmentationChange SupervoxelSegmenter::replace_all(std::span<const VoxelSample> voxels) {
  std::unordered_set<uint64_t> keep;
  keep.reserve(voxels.size());
  for (const VoxelSample& v : voxels)
    if (!v.removed()) keep.insert(voxel_key(v.key));
  std::vector<VoxelSample> all(voxels.begin(), voxels.end());
  voxels_.for_each([&](uint64_t key, const VoxelRec& rec) {
    if (keep.count(key) != 0) return;
    VoxelSample gone = rec.sample;
    gone.flags |= kVoxelRemoved;
    all.push_back(gone);
  });
  return update(all);
}

}  // namespace hexplore::highlevel
