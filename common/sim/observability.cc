#include "common/sim/observability.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <sstream>
#include <thread>
#include <unordered_map>
#include <unordered_set>

#include "common/core/seed_key.h"
#include "common/sim/terrain_probe.h"

namespace hexplore::sim {
namespace {

constexpr double kLevelM = 0.5;     // vertical quantum telling floors apart in the flood fill
constexpr double kSubstepM = 0.1;   // move checks along an edge, fine enough for the step test

struct Node {
  Footprint footprint;
};

// The level is offset by a quarter so float noise around a floor stays in one level.
uint64_t state_key(const Eigen::Vector2d& xy, double z, double grid) {
  return core::seed_key({static_cast<int32_t>(std::floor(xy.x() / grid)), static_cast<int32_t>(std::floor(xy.y() / grid)),
                         static_cast<int32_t>(std::floor(z / kLevelM + 0.25))});
}

// Moves the footprint from `from` to `to_xy` in substeps; the final footprint, or nullopt.
std::optional<Footprint> traverse(const TerrainProbe& probe, const Footprint& from, const Eigen::Vector2d& to_xy) {
  const Eigen::Vector2d delta = to_xy - from.xy;
  const double yaw = std::atan2(delta.y(), delta.x());
  // The turned pose must fit (slope, clearance); its sample points search from where the
  // body's points were (support is only searched a step above them).
  auto f = probe.footprint(from.xy, yaw, from.heights);
  if (!f) return std::nullopt;
  const TerrainVerdict turn = probe.check(*f, nullptr);
  if (turn == TerrainVerdict::kSlope || turn == TerrainVerdict::kClearance || turn == TerrainVerdict::kStep)
    return std::nullopt;
  const int steps = std::max(1, static_cast<int>(std::ceil(delta.norm() / kSubstepM)));
  for (int s = 1; s <= steps; ++s) {
    const auto next = probe.footprint(from.xy + delta * (static_cast<double>(s) / steps), yaw, f->heights);
    if (!next || probe.check(*next, &*f) != TerrainVerdict::kOk) return std::nullopt;
    f = next;
  }
  return f;
}

}  // namespace

std::vector<Eigen::Vector3d> reachable_ground(const RayCaster& caster, const core::SpeciesConfig& species,
                                              std::span<const Eigen::Vector3d> starts,
                                              const Eigen::AlignedBox3d& region, const ObservabilityOptions& options) {
  const TerrainProbe probe(caster, species);
  const double g = options.grid_m;
  std::vector<Eigen::Vector3d> out;
  std::unordered_set<uint64_t> seen;
  std::deque<Footprint> queue;
  for (const auto& s : starts) {
    // Snap to the cell centre so every robot's grid is the same.
    const Eigen::Vector2d c((std::floor(s.x() / g) + 0.5) * g, (std::floor(s.y() / g) + 0.5) * g);
    auto f = probe.footprint(c, 0.0, s.z());
    if (!f) f = probe.footprint(s.head<2>(), 0.0, s.z());
    if (!f) continue;
    if (seen.insert(state_key(f->xy, f->ground_z, g)).second) {
      queue.push_back(*f);
      out.emplace_back(f->xy.x(), f->xy.y(), f->ground_z);
    }
  }
  const Eigen::Vector2d dirs[4] = {{g, 0}, {-g, 0}, {0, g}, {0, -g}};
  while (!queue.empty() && seen.size() < options.max_cells) {
    const Footprint here = queue.front();
    queue.pop_front();
    for (const auto& d : dirs) {
      const Eigen::Vector2d to = here.xy + d;
      if (to.x() < region.min().x() || to.x() > region.max().x() || to.y() < region.min().y() ||
          to.y() > region.max().y())
        continue;
      auto f = traverse(probe, here, to);
      // A door only a little wider than the body is passed only by a body lined up with it,
      // which a straight move from a cell centre rarely is: try again from a quarter or half a
      // cell aside (turn, sidestep, go on), as a driver lines up with a door.
      const Eigen::Vector2d aside(-d.y(), d.x());
      for (const double s : {0.25, -0.25, 0.5, -0.5}) {
        if (f) break;
        const auto jog = traverse(probe, here, here.xy + s * aside);
        if (jog) f = traverse(probe, *jog, jog->xy + d);
      }
      if (!f) continue;
      if (!seen.insert(state_key(f->xy, f->ground_z, g)).second) continue;
      queue.push_back(*f);
      out.emplace_back(f->xy.x(), f->xy.y(), f->ground_z);
    }
  }
  return out;
}

std::vector<uint8_t> observable_mask(const RayCaster& caster, const SurfaceSamples& samples,
                                     const core::TeamConfig& team, const Eigen::AlignedBox3d& region,
                                     const ObservabilityOptions& options) {
  struct Viewpoint {
    Eigen::Vector3f eye;
    float range;
  };
  std::vector<Viewpoint> views;
  for (const auto& species : team.species) {
    std::vector<Eigen::Vector3d> starts;
    for (const auto& r : team.robots)
      if (r.species == species.name) starts.push_back(r.start_position_m);
    if (starts.empty() || species.lidars.empty()) continue;
    double range = 0.0, mount_z = 0.0;
    for (const auto& l : species.lidars) {
      range = std::max(range, l.max_range_m);
      mount_z = std::max(mount_z, l.mount_offset_m.z());
    }
    const double eye_height = species.body_half_extents_m.z() + mount_z;
    // One viewpoint per thinning cell and floor: the reachable point nearest the cell's centre,
    // so the choice depends on what is reachable, not on the order the flood fill found it in.
    const double spacing = options.viewpoint_spacing_m;
    std::map<uint64_t, std::pair<double, Eigen::Vector3d>> thinned;
    for (const auto& p : reachable_ground(caster, species, starts, region, options)) {
      const Eigen::Vector2d centre = ((p.head<2>() / spacing).array().floor() + 0.5).matrix() * spacing;
      const double d2 = (p.head<2>() - centre).squaredNorm();
      auto [it, fresh] = thinned.try_emplace(state_key(p.head<2>(), p.z(), spacing), d2, p);
      if (!fresh && d2 < it->second.first) it->second = {d2, p};
    }
    for (const auto& [key, best] : thinned) {
      const Eigen::Vector3d& p = best.second;
      views.push_back({Eigen::Vector3f(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                       static_cast<float>(p.z() + eye_height)),
                       static_cast<float>(range)});
    }
  }
  std::vector<uint8_t> mask(samples.points.size(), 0);
  if (views.empty()) return mask;

  // Samples are grouped in 4 m cells; each cell gets the viewpoints nearest its centre once
  // (a few times more than are tried, since a sample may sit anywhere in its cell), and a
  // sample only re-ranks that short list.
  constexpr double kCellM = 4.0;
  const size_t want = static_cast<size_t>(std::max(1, options.max_candidates));
  const size_t shortlist = 4 * want;
  auto cell_key = [](const Eigen::Vector3f& p) { return core::seed_key(core::cell_of(p.cast<double>(), kCellM)); };
  std::unordered_map<uint64_t, std::vector<uint32_t>> lists;
  for (const auto& p : samples.points) lists.emplace(cell_key(p), std::vector<uint32_t>{});
  const float half_diagonal = static_cast<float>(kCellM * std::sqrt(3.0) / 2);
  for (auto& [key, list] : lists) {
    const Eigen::Vector3f centre = core::cell_center(core::cell_of_key(key), kCellM).cast<float>();
    std::vector<std::pair<float, uint32_t>> ranked;
    for (uint32_t v = 0; v < views.size(); ++v) {
      const float d = (views[v].eye - centre).norm();
      if (d <= views[v].range + half_diagonal) ranked.emplace_back(d, v);
    }
    const size_t k = std::min(ranked.size(), shortlist);
    std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(k), ranked.end());
    for (size_t i = 0; i < k; ++i) list.push_back(ranked[i].second);
  }

  auto work = [&](size_t begin, size_t end) {
    std::vector<std::pair<float, uint32_t>> near;
    for (size_t i = begin; i < end; ++i) {
      const Eigen::Vector3f& p = samples.points[i];
      near.clear();
      for (uint32_t v : lists.at(cell_key(p))) {
        const float d = (views[v].eye - p).norm();
        if (d <= views[v].range) near.emplace_back(d, v);
      }
      const size_t k = std::min(near.size(), want);
      std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(k), near.end());
      for (size_t c = 0; c < k; ++c) {
        const float d = near[c].first;
        if (d < 1e-3f || !caster.occluded(p, (views[near[c].second].eye - p) / d, 0.02f, d - 0.02f)) {
          mask[i] = 1;
          break;
        }
      }
    }
  };
  // Queries are thread-safe: split the samples over the cores.
  const size_t threads = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 16);
  const size_t chunk = (samples.points.size() + threads - 1) / threads;
  std::vector<std::thread> pool;
  for (size_t t = 0; t < threads; ++t) {
    const size_t begin = t * chunk, end = std::min(samples.points.size(), begin + chunk);
    if (begin < end) pool.emplace_back(work, begin, end);
  }
  for (auto& th : pool) th.join();
  return mask;
}

std::string observability_key(const std::string& scene, uint64_t seed, const core::TeamConfig& team) {
  std::ostringstream s;
  s.precision(6);
  s << scene << '#' << seed;
  for (const auto& sp : team.species) {
    s << '|' << sp.name << ':' << sp.max_slope_deg << ',' << sp.max_step_m << ',' << sp.min_clearance_m << ','
      << sp.body_half_extents_m.transpose();
    for (const auto& l : sp.lidars) s << ',' << l.max_range_m << '@' << l.mount_offset_m.z();
  }
  for (const auto& r : team.robots) s << '|' << r.species << '@' << r.start_position_m.transpose();
  return s.str();
}

}  // namespace hexplore::sim
