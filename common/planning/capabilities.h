#pragma once
// What the planner needs to know about the team: per species its capability levels
// (a_zeta, a_varsigma), observation range and speeds, and per robot its species. Built from
// core::TeamConfig; the no-hetero ablation flattens it to identical robots.

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hexplore::core {
struct TeamConfig;
struct AlgorithmParams;
}

namespace hexplore::planning {

struct SpeciesCapability {
  std::string name;
  int traversal_level = 1;             // a_zeta(k)
  int observation_level = 1;           // a_varsigma(k)
  double observation_range_m = 10.0;   // varsigma_k
  double speed_mps = 0.5;              // vartheta_zeta(k)
  double observation_speed = 1.0;      // vartheta_varsigma(k), facade views per second
};

struct TeamCapabilities {
  std::vector<SpeciesCapability> species;   // index = team species index
  std::vector<std::string> robot_ids;       // index = team robot index
  std::vector<int> robot_species;
  // Whose terrain a species' paths, distances and reachable ground use on the topology graph
  // (index = species): itself, except in the NoHetero ablation. Empty = itself.
  std::vector<int> graph_species;

  int graph_species_of(int k) const { return size_t(k) < graph_species.size() ? graph_species[size_t(k)] : k; }
  double max_observation_range() const;
  // The paper's NoHetero ablation: every robot as capable as the weakest species, in every
  // mechanism the paper makes heterogeneous: traversal (graph levels, reachability, paths
  // and distances all use the species with the lowest traversal level), observation (the
  // shortest range, level 1, so all views are public). Speeds and observation speeds are the
  // robots' own: they are how fast a body moves and scans, not capabilities.
  TeamCapabilities homogeneous() const;
};

TeamCapabilities capabilities_from(const core::TeamConfig& team);

// The planner's tunables: the paper's parameters plus implementation choices.
struct PlannerOptions {
  double gamma_th_deg = 45.0;   // incidence-angle threshold
  double theta_l_deg = -45.0;   // observation-angle bounds (elevation of the target seen from the view)
  double theta_u_deg = 45.0;
  // Kept inside both angle limits where a spot stands in for other targets' views
  // (core::AlgorithmParams::shared_view_angle_margin_deg).
  double shared_view_margin_deg = 0.0;
  double beta_i = 0.5, beta_l = 0.5;            // Vis weights
  // A facade target's task view is the best within the shortest species range that sees it
  // (core::AlgorithmParams::task_view_choice "weakest_species"); false: the best within the
  // team's longest range ("best_score").
  bool weakest_species_views = true;
  double beta_zeta = 10.0, beta_varsigma = 1.0; // capability score a(k)
  // delta(tau, k) charges the cover of a cluster's targets (core::AlgorithmParams::cluster_work
  // "cover"); false: every task view ("every_view"). Planners whose tours visit every view of a
  // cluster charge every view whatever this says.
  bool cover_cluster_work = true;
  double beta_e = 0.5, beta_c = 1.0, beta_m = 1.5, beta_d = 3.0;
  int reference_window = 2;     // core::AlgorithmParams::reference_window
  double eta_s_m = 1.0;         // supervoxel seed interval (ray-cast cell size)
  double eta_r_m = 5.0;         // clustering radius and MNSS neighbourhood
  double sensor_height_m = 0.5; // view (sensor) height above its ground supervoxel centre
  double ground_cover_radius_m = 1.5;  // a view covers ground-ISE supervoxels this close
  // Half the extent of a facade target (a supervoxel grows about 0.75 eta_s from its seed):
  // a view must see its edges, not only its centre, within gamma_th. 0 = a point target.
  double target_half_extent_m = 0.25;
  int ga_population = 64;
  int ga_max_generations = 400;
  double ga_time_budget_s = 0.05;
  uint64_t seed = 1;
  // Local search (2-opt + relocate) on each new best of the GA; false = the paper's plain GA.
  bool ga_memetic = true;
  int mnss_samples = 16;        // view sets sampled per cluster
  double min_view_separation_m = 1.0;  // MNSS rejects views this close to a chosen one
  // Clock of the stage timings and the GA time budget: wall time in services; the thread's
  // CPU time in benchmarks on a shared machine.
  bool cpu_clock = false;
  // Coverage targets (ISE supervoxels) outside this box get no task view; unbounded by default.
  Eigen::AlignedBox3d region = unbounded();

  static Eigen::AlignedBox3d unbounded() {
    const double inf = std::numeric_limits<double>::infinity();
    return Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-inf), Eigen::Vector3d::Constant(inf));
  }

  static PlannerOptions from(const core::AlgorithmParams& params);
};

}  // namespace hexplore::planning
