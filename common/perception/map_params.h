#pragma once
// Parameters of one robot's perception map: grid resolution, the paper's coverage and
// partition thresholds (rho_th, gamma_th, s_th, l_th) and the terrain limits of every
// species of the team, in team-config order (bit k of a risk mask = species index k).

#include <cstdint>
#include <string>
#include <vector>

#include "common/core/team_config.h"

namespace hexplore::perception {

// Terrain limits of one species; R_k(v) = 0 only when a voxel satisfies all of them.
struct SpeciesLimits {
  std::string name;
  double max_slope_deg = 15.0;
  double max_step_m = 0.05;
  double max_roughness_m = 0.03;
  double min_clearance_m = 0.6;
  double max_sparsity = 0.9;
  // Body length along its travel; 0: none known. With it, slopes are allowed up to the
  // allowance below rather than max_slope_deg itself.
  double body_length_m = 0.0;
};

// The steepest voxel slope a species is taken to cross: its max slope plus half a step over its
// body length, the tolerance the simulated body gets too (common/sim/terrain_probe.cc). A
// tracked body bridges stair nosings and feels a flight's mean slope, while voxel normals
// fitted to 0.45 m of a staircase read up to ~10 deg steeper where risers dominate; without the
// allowance a 30 deg flight is high risk for a 35 deg species in patches that cut the flight.
double slope_allowance_deg(const SpeciesLimits& s);

// Why 0.15 m: the paper's supervoxel edge eta_e = 0.2 m must span at least one voxel, a
// voxel must resolve a 15 cm step (the wheeled species' limit case) as a height change of one
// cell, and a 0.1 m grid would triple the voxel count (memory, fusion time, delta traffic) of a
// building-scale map for no gain in the terrain metrics, which fuse a 3x3x3 neighbourhood anyway.
struct MapParams {
  double resolution_m = 0.15;
  // Observation density rho(v) is measured in points per cm^2 of surface inside the voxel
  // (surface area taken as resolution^2; kFusedSurface: the area fitted to the neighbourhood). rho_th = 0.3 points/cm^2 then asks for
  // ~68 points in a 0.15 m voxel: a few frames from a 16-120 line LiDAR within ~10 m, but never
  // one far grazing sweep. The unit does not depend on the resolution.
  double rho_th = 0.3;
  // What rho(v) measures (core::AlgorithmParams::rho_measure).
  enum class Density { kQualifyingPoints, kAllPoints, kNeighbourOccupancy, kFusedSurface };
  Density density = Density::kAllPoints;
  double gamma_th_deg = 45.0;  // observation angle threshold (facade)
  double gamma_th_ground_deg = 75.0;  // observation angle threshold (ground; see core::AlgorithmParams)
  double s_th_deg = 45.0;      // ground/facade slope threshold
  double l_th_m = 10.0;        // observation distance threshold of THIS robot's species
  // A published voxel is re-sent only when its mean moved or its normal turned more than this
  // (flags and risk masks are always re-sent on change).
  double mean_tolerance_m = 0.01;
  double normal_tolerance_deg = 5.0;
  // Teammate body boxes are grown by this margin before filtering (pose latency, LiDAR noise).
  double teammate_box_margin_m = 0.1;
  // A neighbourhood with fewer points, or spread along a line only, gives no normal.
  uint32_t min_points_for_normal = 4;
  std::vector<SpeciesLimits> species;

  // Throws std::invalid_argument naming the bad field.
  void validate() const;
  // Points per cm^2 represented by one point in a voxel.
  double density_per_point() const { return 1.0 / (resolution_m * resolution_m * 1.0e4); }
};

SpeciesLimits species_limits(const core::SpeciesConfig& species);

// Map parameters of robot `robot_id` of `team`: thresholds from team.params, l_th from the
// robot's species observation range, limits of every species of the team.
// Throws std::invalid_argument when the robot or its species is unknown.
MapParams make_map_params(const core::TeamConfig& team, const std::string& robot_id);

// Same, from parts (tests, tools).
MapParams make_map_params(const core::AlgorithmParams& params,
                          const std::vector<core::SpeciesConfig>& team_species,
                          const core::SpeciesConfig& own_species);

}  // namespace hexplore::perception
