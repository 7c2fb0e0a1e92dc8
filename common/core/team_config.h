#pragma once
// The team description every service reads: species (mobility and sensing limits),
// robots, endpoints and the paper's algorithm parameters. Loaded from one YAML file
// (see deploy/teams/*.yaml); defaults are the paper's parameter table.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "common/core/liveness.h"

namespace hexplore::core {

// One rotating multi-line LiDAR (or a gimballed one). Angles in degrees in the sensor frame
// (x forward, z up); elevation 0 is horizontal.
struct LidarConfig {
  std::string name;
  int lines = 16;                       // vertical channels, evenly spaced over the vertical FoV
  double vertical_min_deg = -15.0;
  double vertical_max_deg = 15.0;
  double horizontal_min_deg = -180.0;   // azimuth range; 360 deg span = full rotation
  double horizontal_max_deg = 180.0;
  double horizontal_step_deg = 0.2;     // azimuth resolution
  double min_range_m = 0.3;
  double max_range_m = 40.0;
  double range_noise_stddev_m = 0.01;
  Eigen::Vector3d mount_offset_m = Eigen::Vector3d::Zero();  // sensor origin in the body frame
  double mount_pitch_deg = 0.0;         // fixed mount pitch (positive = nose up)
  bool gimbal = false;                  // yaw/pitch gimbal that aims the sensor at a target
  // Livox-style non-repetitive scanning: each frame's pattern is turned by a random fraction
  // of the line spacing and column step, so a sensor that stands still keeps filling the gaps
  // between its lines (a rotating LiDAR's fixed pattern would hit the same points forever).
  bool non_repetitive = false;

  int rays_per_frame() const;
};

// A robot species: mobility limits, speeds, observation capability and sensors.
struct SpeciesConfig {
  std::string name;
  int traversal_level = 1;              // a_zeta(k): 1 = least capable; higher climbs more
  // Terrain limits a voxel must satisfy to be low-risk for this species (R_k(v) = 0).
  double max_slope_deg = 15.0;
  double max_step_m = 0.05;             // largest height jump between adjacent ground cells
  double max_roughness_m = 0.03;        // largest std-dev of heights across the footprint
  double min_clearance_m = 0.6;         // free space needed above the ground (body height)
  double max_sparsity = 0.9;            // fraction of empty neighbour cells tolerated
  // Motion and observation.
  double speed_mps = 0.5;               // vartheta_zeta(k)
  double observation_speed_views_per_s = 1.0;  // vartheta_varsigma(k)
  double observation_range_m = 10.0;    // varsigma_k and l_th for this species
  Eigen::Vector3d body_half_extents_m = Eigen::Vector3d(0.4, 0.3, 0.3);
  std::vector<LidarConfig> lidars;
};

// One robot of the team.
struct RobotConfig {
  std::string id;
  std::string species;
  Eigen::Vector3d start_position_m = Eigen::Vector3d::Zero();
  double start_yaw_deg = 0.0;
};

// The team radio as the simulation models it (transport.radio; common/transport/link_model.h).
// All zero is an ideal link. Applies to the team topics between robots; the station, a
// recorder of the experiment, hears and is heard directly.
// A robot cut off from every teammate for a while (a partition that heals), in sim seconds
// [from_s, to_s). Modelled where the loop's clock is sim time (lockstep).
struct RadioOutage {
  std::string robot;
  double from_s = 0.0;
  double to_s = 0.0;
};

struct RadioConfig {
  double bandwidth_bytes_per_s = 0.0;  // each robot's transmit capacity; 0 = unlimited
  double latency_s = 0.0;              // added to every message once it left the queue
  double loss = 0.0;                   // chance that one receiver misses one message, [0, 1)
  double range_m = 0.0;                // robots farther apart hear nothing of each other; 0 = unlimited
  double max_queue_age_s = 2.0;        // a message that would wait longer for the channel is dropped
  std::vector<RadioOutage> outages;    // partitions: no link to or from the robot while one lasts

  bool active() const {
    return bandwidth_bytes_per_s > 0.0 || latency_s > 0.0 || loss > 0.0 || range_m > 0.0 || !outages.empty();
  }
};

// Where the services listen. Every service binds one PUB socket and one ROUTER socket;
// ports are base_port + robot_index * ports_per_robot + service offset (see endpoints.h).
struct TransportConfig {
  std::string scheme = "tcp";            // tcp | ipc | inproc
  std::string host_template = "127.0.0.1";  // "{robot}" and "{service}" are substituted
  int base_port = 17000;
  int ports_per_robot = 20;
  std::string ipc_dir = "/tmp/hexplore";
  int send_high_water_mark = 10000;
  int receive_high_water_mark = 10000;
  int64_t max_message_bytes = 64 * 1024 * 1024;
  int linger_ms = 1000;                  // how long a closing socket may flush queued messages
  // CURVE authentication and encryption of every tcp socket (common/transport/curve_keys.h):
  // the folder of the team's key pairs, one per robot and one for the station (hexplore_keys
  // writes them); relative to the team file's folder. "" = plain ZeroMQ.
  std::string curve_keys_dir;
  RadioConfig radio;
};

// The paper's parameter table (defaults) plus implementation choices.
struct AlgorithmParams {
  // Perception map.
  double map_resolution_m = 0.15;
  double rho_th = 0.3;                   // observation-density threshold, points per cm^2 (see perception/map_params.h)
  // What rho(v) measures (common/planning/README.md, "The coverage model", has the measured
  // difference): "all_points": points of the voxel per cm^2 (the density of its point cloud);
  // "qualifying_points": only points of observations within the angle and distance thresholds;
  // "neighbour_occupancy": 1 - sparsity, the occupied share of the voxel's 26 neighbours (the
  // paper: density "is inversely proportional to the sparsity in terrain metrics");
  // "fused_surface": points of the voxel's 3x3x3 neighbourhood per cm^2 of the surface fitted
  // to them (the fused Gaussian the normal comes from; the paper: "points per unit area").
  std::string rho_measure = "all_points";
  // Smallest connected patch of ISE voxels that keeps a supervoxel an ISE
  // (highlevel::SegmenterParams::min_ise_patch_voxels; 1 = every voxel must be covered).
  int min_ise_patch_voxels = 1;
  double gamma_th_deg = 45.0;            // observation-angle threshold (facade voxels)
  // Observation-angle threshold for ground voxels. Not in the paper's table: a LiDAR mounted
  // below 1 m sees the floor at grazing angles, and with 45 deg a floor voxel would need the
  // sensor within one mount height of it, so ground coverage would never complete. 75 deg
  // covers the floor within about 2 m of the robot, matching the paper's assumption that a
  // ground supervoxel is observed once a robot reaches its centre.
  double gamma_th_ground_deg = 75.0;
  double s_th_deg = 45.0;                // ground / facade slope threshold
  // Task views.
  double theta_l_deg = -45.0;
  double theta_u_deg = 45.0;
  // Margin the planner keeps inside gamma_th and [theta_l, theta_u] when a spot is to stand in
  // for other targets' own views (the minimal view set, route pruning, MROMT+'s candidates,
  // observations in passing; not in the paper): a target is complete only when every voxel
  // passes gamma_th on its own normal, and voxel normals scatter around the supervoxel's. Each
  // target's own task view keeps the paper's limits.
  double shared_view_angle_margin_deg = 0.0;
  // Where a facade target's task view is chosen: "weakest_species" (the best view within the
  // shortest species range that sees the target, so the target stays public when the weaker
  // species can take it) or "best_score" (the best view within the team's longest range, the
  // paper read literally; planning::PlannerOptions::weakest_species_views).
  std::string task_view_choice = "weakest_species";
  double beta_i = 0.5;
  double beta_l = 0.5;
  double beta_zeta = 10.0;
  double beta_varsigma = 1.0;
  // What the execution time delta(tau, k) of a cluster charges (planning/cluster_work.h):
  // "cover" (the views that together see the cluster's targets, as its MNSS tour stands at) or
  // "every_view" (a walk to and a dwell at every task view: the paper's formula as written).
  std::string cluster_work = "cover";
  // Assignment fitness.
  double beta_e = 0.5;
  double beta_c = 1.0;
  double beta_m = 1.5;
  double beta_d = 3.0;
  // How far ahead along the reference route the i-th cluster of a new route may match it, in
  // reference segments (i + window); -1: any segment, the paper's literal "all such segments".
  // Matched against the whole polyline, a route that runs the reference backwards is as close
  // as one that follows it, and robots turned round between rounds
  // (common/planning/README.md, "Routes that turn round").
  int reference_window = 2;
  // Supervoxels, sharing, clustering, safety, replanning.
  double eta_e_m = 0.2;
  double eta_s_m = 1.0;
  double eta_c_s = 1.0;
  double eta_r_m = 5.0;
  double eta_p_m = 2.0;
  double eta_t_s = 10.0;
  // Seconds of silence after which a teammate counts as gone, per use (core/liveness.h).
  LivenessParams liveness;
  // Genetic algorithm budget.
  int ga_population = 64;
  int ga_max_generations = 400;
  double ga_time_budget_s = 0.05;
  // Planner and reproducibility.
  std::string planner = "hexplore";
  uint64_t seed = 1;
  // The planners' own random stream (GA, MNSS, VRP search); 0: the team's seed. Set alone, it
  // perturbs a mission without changing its scene, sensing or radio: how far runs of one seed
  // drift apart under it is how much of a difference between two trees a seed can show.
  uint64_t planner_seed = 0;
};

// How a scene given as a mesh file is placed in the world (ignored for built-in scenes): the
// sim and the station's evaluator must load the same world, so this lives in the team file.
struct SceneImport {
  std::string up_axis = "z";  // "z", or "y" for Y-up files: (x, y, z) <- (x, -z, y)
  double scale = 1.0;         // multiplies coordinates after the up-axis change (0.001: millimetres)
  double yaw_deg = 0.0;       // rotation about z after scaling
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();  // applied last
};

// The whole team file.
struct TeamConfig {
  std::string source_file;               // where it was loaded from, for error messages
  std::string scene = "single-building";
  SceneImport scene_import;
  std::vector<SpeciesConfig> species;
  std::vector<RobotConfig> robots;
  TransportConfig transport;
  AlgorithmParams params;
  int metrics_base_port = 0;             // 0 = no Prometheus exposer; else base + robot*10 + service
  double time_limit_s = 1800.0;          // mission ends at this sim time if views remain
  // The area the operator asks the team to explore (world frame). Surfaces outside it are
  // not coverage targets; robots may still drive outside it. Unbounded when not given.
  Eigen::AlignedBox3d exploration_region = unbounded_region();

  static Eigen::AlignedBox3d unbounded_region() {
    const double inf = std::numeric_limits<double>::infinity();
    return Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-inf), Eigen::Vector3d::Constant(inf));
  }

  // Lookups; nullptr / nullopt when unknown, never throw.
  const SpeciesConfig* find_species(const std::string& name) const;
  const RobotConfig* find_robot(const std::string& id) const;
  std::optional<int> robot_index(const std::string& id) const;
  std::optional<int> species_index(const std::string& name) const;

  // Observation-capability level a_varsigma(k): species ranked by observation range, ties share.
  int observation_level(const SpeciesConfig& s) const;
};

// Parses and validates a team file; throws ConfigError naming file, key and problem.
TeamConfig load_team_config(const std::string& path);
// Same, from YAML text (tests, embedded defaults); `origin` names it in errors.
TeamConfig parse_team_config(const std::string& yaml_text, const std::string& origin);
// Checks cross-references and ranges; throws ConfigError.
void validate(const TeamConfig& config);

// The paper's two species and a legged third, as built-in templates a team file can refer
// to by name (`builtin: NAME`).
SpeciesConfig builtin_slugcat();
SpeciesConfig builtin_mr1000();
SpeciesConfig builtin_quadruped();
// The built-in names, and the template of one; nullopt for another name.
std::vector<std::string> builtin_species_names();
std::optional<SpeciesConfig> builtin_species(const std::string& name);

}  // namespace hexplore::core
