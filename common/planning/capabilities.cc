#include "common/planning/capabilities.h"

#include <algorithm>

#include "common/core/team_config.h"

namespace hexplore::planning {

double TeamCapabilities::max_observation_range() const {
  double m = 0.0;
  for (const auto& s : species) m = std::max(m, s.observation_range_m);
  return m;
}

TeamCapabilities TeamCapabilities::homogeneous() const {
  TeamCapabilities out = *this;
  if (species.empty()) return out;
  int level = species.front().traversal_level;
  int weakest = 0;  // lowest traversal level; ties: lower index
  double range = species.front().observation_range_m;
  for (size_t k = 0; k < species.size(); ++k) {
    if (species[k].traversal_level < level) level = species[k].traversal_level, weakest = int(k);
    range = std::min(range, species[k].observation_range_m);
  }
  for (auto& s : out.species) {
    s.traversal_level = level;
    s.observation_level = 1;
    s.observation_range_m = range;
  }
  out.graph_species.assign(species.size(), weakest);
  return out;
}

TeamCapabilities capabilities_from(const core::TeamConfig& team) {
  TeamCapabilities caps;
  for (const auto& s : team.species)
    caps.species.push_back({s.name, s.traversal_level, team.observation_level(s), s.observation_range_m, s.speed_mps,
                            s.observation_speed_views_per_s});
  for (const auto& r : team.robots) {
    caps.robot_ids.push_back(r.id);
    caps.robot_species.push_back(team.species_index(r.species).value_or(0));
  }
  return caps;
}

PlannerOptions PlannerOptions::from(const core::AlgorithmParams& p) {
  PlannerOptions o;
  o.gamma_th_deg = p.gamma_th_deg;
  o.theta_l_deg = p.theta_l_deg;
  o.theta_u_deg = p.theta_u_deg;
  o.shared_view_margin_deg = p.shared_view_angle_margin_deg;
  o.weakest_species_views = p.task_view_choice == "weakest_species";
  o.cover_cluster_work = p.cluster_work == "cover";
  o.beta_i = p.beta_i;
  o.beta_l = p.beta_l;
  o.beta_zeta = p.beta_zeta;
  o.beta_varsigma = p.beta_varsigma;
  o.beta_e = p.beta_e;
  o.beta_c = p.beta_c;
  o.beta_m = p.beta_m;
  o.beta_d = p.beta_d;
  o.reference_window = p.reference_window;
  o.eta_s_m = p.eta_s_m;
  o.eta_r_m = p.eta_r_m;
  o.ga_population = p.ga_population;
  o.ga_max_generations = p.ga_max_generations;
  o.ga_time_budget_s = p.ga_time_budget_s;
  o.seed = p.planner_seed != 0 ? p.planner_seed : p.seed;
  return o;
}

}  // namespace hexplore::planning
