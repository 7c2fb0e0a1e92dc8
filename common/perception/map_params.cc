#include "common/perception/map_params.h"

#include <cmath>
#include <stdexcept>

namespace hexplore::perception {
namespace {

void require(bool ok, const std::string& field, const std::string& problem) {
  if (!ok) throw std::invalid_argument("perception MapParams." + field + ": " + problem);
}

}  // namespace

void MapParams::validate() const {
  require(std::isfinite(resolution_m) && resolution_m >= 0.01 && resolution_m <= 2.0, "resolution_m",
          "must be in [0.01, 2] m, got " + std::to_string(resolution_m));
  require(std::isfinite(rho_th) && rho_th >= 0.0, "rho_th", "must be >= 0");
  require(gamma_th_deg > 0.0 && gamma_th_deg <= 90.0, "gamma_th_deg", "must be in (0, 90]");
  require(gamma_th_ground_deg > 0.0 && gamma_th_ground_deg <= 90.0, "gamma_th_ground_deg", "must be in (0, 90]");
  require(s_th_deg > 0.0 && s_th_deg < 180.0, "s_th_deg", "must be in (0, 180)");
  require(std::isfinite(l_th_m) && l_th_m > 0.0, "l_th_m", "must be > 0");
  require(mean_tolerance_m >= 0.0, "mean_tolerance_m", "must be >= 0");
  require(normal_tolerance_deg >= 0.0, "normal_tolerance_deg", "must be >= 0");
  require(teammate_box_margin_m >= 0.0, "teammate_box_margin_m", "must be >= 0");
  require(min_points_for_normal >= 3, "min_points_for_normal", "must be >= 3");
  require(!species.empty(), "species", "the team has no species");
  require(species.size() <= 32, "species", "at most 32 species fit the 32-bit risk mask");
  for (const SpeciesLimits& s : species) {
    const std::string f = "species[" + s.name + "].";
    require(s.max_slope_deg >= 0.0 && s.max_slope_deg <= 90.0, f + "max_slope_deg", "must be in [0, 90]");
    require(s.max_step_m >= 0.0 && s.max_step_m <= 2.0, f + "max_step_m", "must be in [0, 2] m");
    require(s.max_roughness_m >= 0.0, f + "max_roughness_m", "must be >= 0");
    require(s.min_clearance_m >= 0.0 && s.min_clearance_m <= 5.0, f + "min_clearance_m", "must be in [0, 5] m");
    require(s.max_sparsity >= 0.0 && s.max_sparsity <= 1.0, f + "max_sparsity", "must be in [0, 1]");
    require(s.body_length_m >= 0.0, f + "body_length_m", "must be >= 0");
  }
}

double slope_allowance_deg(const SpeciesLimits& s) {
  if (s.body_length_m <= 0.0 || s.max_slope_deg >= 90.0) return s.max_slope_deg;
  const double tan_allowed = std::tan(s.max_slope_deg * M_PI / 180.0) + 0.5 * s.max_step_m / s.body_length_m;
  return std::atan(tan_allowed) * 180.0 / M_PI;
}

SpeciesLimits species_limits(const core::SpeciesConfig& s) {
  SpeciesLimits l;
  l.name = s.name;
  l.max_slope_deg = s.max_slope_deg;
  l.body_length_m = 2.0 * s.body_half_extents_m.x();
  l.max_step_m = s.max_step_m;
  l.max_roughness_m = s.max_roughness_m;
  l.min_clearance_m = s.min_clearance_m;
  l.max_sparsity = s.max_sparsity;
  return l;
}

MapParams make_map_params(const core::AlgorithmParams& params,
                          const std::vector<core::SpeciesConfig>& team_species,
                          const core::SpeciesConfig& own_species) {
  MapParams p;
  p.resolution_m = params.map_resolution_m;
  p.rho_th = params.rho_th;
  p.density = params.rho_measure == "qualifying_points"     ? MapParams::Density::kQualifyingPoints
              : params.rho_measure == "neighbour_occupancy" ? MapParams::Density::kNeighbourOccupancy
              : params.rho_measure == "fused_surface"       ? MapParams::Density::kFusedSurface
                                                            : MapParams::Density::kAllPoints;
  p.gamma_th_deg = params.gamma_th_deg;
  p.gamma_th_ground_deg = params.gamma_th_ground_deg;
  p.s_th_deg = params.s_th_deg;
  p.l_th_m = own_species.observation_range_m;
  for (const core::SpeciesConfig& s : team_species) p.species.push_back(species_limits(s));
  p.validate();
  return p;
}

MapParams make_map_params(const core::TeamConfig& team, const std::string& robot_id) {
  const core::RobotConfig* robot = team.find_robot(robot_id);
  if (robot == nullptr) {
    throw std::invalid_argument("perception: robot '" + robot_id + "' is not in team file " + team.source_file);
  }
  const core::SpeciesConfig* species = team.find_species(robot->species);
  if (species == nullptr) {
    throw std::invalid_argument("perception: species '" + robot->species + "' of robot '" + robot_id +
                                "' is not in team file " + team.source_file);
  }
  return make_map_params(team.params, team.species, *species);
}

}  // namespace hexplore::perception
