#include "common/core/team_config.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "common/core/config_error.h"

namespace hexplore::core {

int LidarConfig::rays_per_frame() const {
  const double span = horizontal_max_deg - horizontal_min_deg;
  const int columns = std::max(1, static_cast<int>(std::lround(span / horizontal_step_deg)));
  return columns * lines;
}

const SpeciesConfig* TeamConfig::find_species(const std::string& name) const {
  for (const auto& s : species)
    if (s.name == name) return &s;
  return nullptr;
}

const RobotConfig* TeamConfig::find_robot(const std::string& id) const {
  for (const auto& r : robots)
    if (r.id == id) return &r;
  return nullptr;
}

std::optional<int> TeamConfig::robot_index(const std::string& id) const {
  for (size_t i = 0; i < robots.size(); ++i)
    if (robots[i].id == id) return static_cast<int>(i);
  return std::nullopt;
}

std::optional<int> TeamConfig::species_index(const std::string& name) const {
  for (size_t i = 0; i < species.size(); ++i)
    if (species[i].name == name) return static_cast<int>(i);
  return std::nullopt;
}

int TeamConfig::observation_level(const SpeciesConfig& s) const {
  // Level = 1 + number of distinct observation ranges strictly below this species' range.
  std::set<double> shorter;
  for (const auto& other : species)
    if (other.observation_range_m < s.observation_range_m) shorter.insert(other.observation_range_m);
  return 1 + static_cast<int>(shorter.size());
}

SpeciesConfig builtin_slugcat() {
  SpeciesConfig s;
  s.name = "SLUGCAT";
  s.traversal_level = 2;
  s.max_slope_deg = 35.0;
  s.max_step_m = 0.25;
  s.max_roughness_m = 0.12;
  s.min_clearance_m = 0.45;
  s.max_sparsity = 0.97;
  s.speed_mps = 0.4;
  s.observation_speed_views_per_s = 10.0;
  s.observation_range_m = 10.0;
  s.body_half_extents_m = {0.45, 0.3, 0.2};
  LidarConfig panoramic;
  panoramic.name = "panoramic";
  panoramic.lines = 120;
  panoramic.vertical_min_deg = -45.0;
  panoramic.vertical_max_deg = 45.0;
  panoramic.horizontal_min_deg = -180.0;
  panoramic.horizontal_max_deg = 180.0;
  panoramic.horizontal_step_deg = 0.2;  // 1,800 columns x 120 lines = 216,000 rays
  panoramic.max_range_m = 40.0;
  panoramic.mount_offset_m = {0.0, 0.0, 0.35};
  panoramic.non_repetitive = true;  // stands in for three Livox Mid360
  s.lidars.push_back(panoramic);
  return s;
}

SpeciesConfig builtin_mr1000() {
  SpeciesConfig s;
  s.name = "MR1000";
  s.traversal_level = 1;
  s.max_slope_deg = 12.0;
  s.max_step_m = 0.08;
  s.max_roughness_m = 0.04;
  s.min_clearance_m = 0.8;
  s.max_sparsity = 0.9;
  s.speed_mps = 0.5;
  s.observation_speed_views_per_s = 0.1;
  s.observation_range_m = 27.0;
  s.body_half_extents_m = {0.5, 0.35, 0.4};
  LidarConfig horizon;
  horizon.name = "gimbal";
  horizon.lines = 32;
  horizon.vertical_min_deg = -11.25;
  horizon.vertical_max_deg = 11.25;
  horizon.horizontal_min_deg = -45.0;
  horizon.horizontal_max_deg = 45.0;
  horizon.horizontal_step_deg = 0.1;
  horizon.max_range_m = 90.0;
  horizon.mount_offset_m = {0.1, 0.0, 0.9};
  horizon.gimbal = true;
  horizon.non_repetitive = true;  // a Livox Horizon
  LidarConfig near_ground;
  near_ground.name = "near_ground";
  near_ground.lines = 80;
  near_ground.vertical_min_deg = -45.0;
  near_ground.vertical_max_deg = 15.0;
  near_ground.horizontal_min_deg = -180.0;
  near_ground.horizontal_max_deg = 180.0;
  near_ground.horizontal_step_deg = 0.5;
  near_ground.max_range_m = 40.0;
  near_ground.mount_offset_m = {0.1, 0.0, 0.7};
  near_ground.non_repetitive = true;  // a Livox Mid360
  s.lidars = {horizon, near_ground};
  return s;
}

// A legged robot of the ANYmal class, between the paper's two species in every terrain limit
// so that the traversal levels still rank what each crosses (MR1000 1 < QUADRUPED 2 <
// SLUGCAT, which a team with both must raise to 3: validate() refuses two species of one
// level with different limits). It walks stairs (0.20 m steps, 30 deg) but not the rubble and
// high debris the tracked SLUGCAT crawls over, and needs more headroom than the SLUGCAT and
// less than the MR1000; it walks fastest of the three (0.6 m/s). Its map joins the floors of a
// flight of 0.15 m risers (the campus scene's), not of the older scenes' 0.175 m ones, though
// its body climbs both. One rotating 32-line LiDAR on its trunk sees all round to mid range:
// observation range 20 m, between SLUGCAT's 10 m and MR1000's 27 m, and 2 s per facade view
// (32 lines lay down points far more slowly than SLUGCAT's panoramic set).
SpeciesConfig builtin_quadruped() {
  SpeciesConfig s;
  s.name = "QUADRUPED";
  s.traversal_level = 2;
  s.max_slope_deg = 30.0;
  s.max_step_m = 0.20;
  s.max_roughness_m = 0.08;
  s.min_clearance_m = 0.70;
  s.max_sparsity = 0.93;
  s.speed_mps = 0.6;
  s.observation_speed_views_per_s = 0.5;
  s.observation_range_m = 20.0;
  s.body_half_extents_m = {0.40, 0.28, 0.30};  // 0.80 x 0.56 m trunk and legs, 0.6 m tall
  LidarConfig rotating;
  rotating.name = "rotating";
  rotating.lines = 32;
  // 90 deg of vertical field, as an Ouster OS0-32: with +-22.5 deg its map of a flight it
  // climbed never joined the floors (it sees too little of the treads ahead of its feet).
  rotating.vertical_min_deg = -45.0;
  rotating.vertical_max_deg = 45.0;
  rotating.horizontal_min_deg = -180.0;
  rotating.horizontal_max_deg = 180.0;
  rotating.horizontal_step_deg = 0.35;  // 1,029 columns x 32 lines = 32,928 rays
  rotating.max_range_m = 50.0;
  rotating.mount_offset_m = {0.1, 0.0, 0.35};  // on top of the trunk, 0.65 m above the ground
  // A rotating LiDAR repeats its pattern, but a legged robot's trunk is never still (gait,
  // balance), so its lines fall elsewhere every frame; the shifted pattern stands in for that.
  rotating.non_repetitive = true;
  s.lidars.push_back(rotating);
  return s;
}

std::vector<std::string> builtin_species_names() { return {"SLUGCAT", "MR1000", "QUADRUPED"}; }

std::optional<SpeciesConfig> builtin_species(const std::string& name) {
  if (name == "SLUGCAT") return builtin_slugcat();
  if (name == "MR1000") return builtin_mr1000();
  if (name == "QUADRUPED") return builtin_quadruped();
  return std::nullopt;
}

namespace {

bool same_terrain_limits(const SpeciesConfig& a, const SpeciesConfig& b) {
  return a.max_slope_deg == b.max_slope_deg && a.max_step_m == b.max_step_m && a.max_roughness_m == b.max_roughness_m &&
         a.min_clearance_m == b.min_clearance_m && a.max_sparsity == b.max_sparsity;
}

void require(bool ok, const TeamConfig& c, const std::string& key, const std::string& problem) {
  if (!ok) throw ConfigError(c.source_file, key, problem);
}

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

}  // namespace

void validate(const TeamConfig& c) {
  require(!c.species.empty(), c, "species", "at least one species is required");
  require(!c.robots.empty(), c, "robots", "at least one robot is required");
  require(c.species.size() <= 32, c, "species", "at most 32 species (risk masks are 32-bit)");
  std::set<std::string> names;
  for (size_t i = 0; i < c.species.size(); ++i) {
    const auto& s = c.species[i];
    const std::string key = "species[" + std::to_string(i) + "]";
    require(!s.name.empty(), c, key + ".name", "must not be empty");
    require(names.insert(s.name).second, c, key + ".name", "duplicate species '" + s.name + "'");
    require(s.traversal_level >= 1, c, key + ".traversal_level", "must be >= 1");
    // A ground cell's requirement is the lowest level of the species that may cross it, and
    // every species of that level or above is sent across: two species of one level must
    // cross the same ground.
    for (size_t j = 0; j < i; ++j)
      require(c.species[j].traversal_level != s.traversal_level || same_terrain_limits(c.species[j], s), c,
              key + ".traversal_level",
              "species '" + s.name + "' and '" + c.species[j].name + "' share traversal level " +
                  std::to_string(s.traversal_level) +
                  " but not their terrain limits; give the one that crosses more a higher level");
    require(s.speed_mps > 0 && std::isfinite(s.speed_mps), c, key + ".speed_mps", "must be a positive number");
    require(s.observation_speed_views_per_s > 0, c, key + ".observation_speed_views_per_s", "must be > 0");
    require(s.observation_range_m > 0, c, key + ".observation_range_m", "must be > 0");
    require(s.max_slope_deg > 0 && s.max_slope_deg < 90, c, key + ".max_slope_deg", "must be in (0, 90)");
    require(s.max_step_m >= 0, c, key + ".max_step_m", "must be >= 0");
    require(s.min_clearance_m >= 0, c, key + ".min_clearance_m", "must be >= 0");
    require(finite(s.body_half_extents_m) && s.body_half_extents_m.minCoeff() > 0, c,
            key + ".body_half_extents_m", "must be three positive numbers");
    for (size_t j = 0; j < s.lidars.size(); ++j) {
      const auto& l = s.lidars[j];
      const std::string lk = key + ".lidars[" + std::to_string(j) + "]";
      require(l.lines >= 1, c, lk + ".lines", "must be >= 1");
      require(l.vertical_max_deg >= l.vertical_min_deg, c, lk + ".vertical_max_deg", "must be >= vertical_min_deg");
      require(l.horizontal_max_deg > l.horizontal_min_deg, c, lk + ".horizontal_max_deg", "must be > horizontal_min_deg");
      require(l.horizontal_step_deg > 0, c, lk + ".horizontal_step_deg", "must be > 0");
      require(l.max_range_m > l.min_range_m && l.min_range_m >= 0, c, lk + ".max_range_m", "must be > min_range_m >= 0");
      require(l.range_noise_stddev_m >= 0, c, lk + ".range_noise_stddev_m", "must be >= 0");
    }
  }
  std::set<std::string> ids;
  for (size_t i = 0; i < c.robots.size(); ++i) {
    const auto& r = c.robots[i];
    const std::string key = "robots[" + std::to_string(i) + "]";
    require(!r.id.empty(), c, key + ".id", "must not be empty");
    require(r.id.find('/') == std::string::npos, c, key + ".id", "must not contain '/' (it is part of topic names)");
    require(ids.insert(r.id).second, c, key + ".id", "duplicate robot id '" + r.id + "'");
    require(c.find_species(r.species) != nullptr, c, key + ".species",
            "unknown species '" + r.species + "'");
    require(finite(r.start_position_m), c, key + ".start", "must be finite numbers");
  }
  const auto& t = c.transport;
  require(t.scheme == "tcp" || t.scheme == "ipc" || t.scheme == "inproc", c, "transport.scheme",
          "must be one of tcp, ipc, inproc (got '" + t.scheme + "')");
  require(t.base_port > 0 && t.base_port < 65535, c, "transport.base_port", "must be a port number");
  require(t.ports_per_robot >= 12, c, "transport.ports_per_robot", "must be >= 12 (6 services x 2 sockets)");
  require(t.max_message_bytes > 0, c, "transport.max_message_bytes", "must be > 0");
  for (size_t i = 0; i < t.radio.outages.size(); ++i)
    require(ids.count(t.radio.outages[i].robot) > 0, c, "transport.radio.outages[" + std::to_string(i) + "].robot",
            "unknown robot '" + t.radio.outages[i].robot + "'");
  const auto& p = c.params;
  require(p.map_resolution_m >= 0.02 && p.map_resolution_m <= 1.0, c, "params.map_resolution_m", "must be in [0.02, 1]");
  require(p.eta_s_m > p.map_resolution_m, c, "params.eta_s_m", "must exceed map_resolution_m");
  require(p.eta_c_s > 0, c, "params.eta_c_s", "must be > 0");
  require(p.eta_r_m > 0, c, "params.eta_r_m", "must be > 0");
  require(p.eta_t_s > 0, c, "params.eta_t_s", "must be > 0");
  require(p.theta_l_deg < p.theta_u_deg, c, "params.theta_u_deg", "must be > theta_l_deg");
  require(p.shared_view_angle_margin_deg >= 0.0 && p.shared_view_angle_margin_deg < p.gamma_th_deg &&
              2.0 * p.shared_view_angle_margin_deg < p.theta_u_deg - p.theta_l_deg,
          c, "params.shared_view_angle_margin_deg", "must be >= 0 and leave room inside gamma_th_deg and [theta_l_deg, theta_u_deg]");
  require(p.ga_population >= 2, c, "params.ga_population", "must be >= 2");
  require(c.time_limit_s > 0, c, "time_limit_s", "must be > 0");
}

}  // namespace hexplore::core
