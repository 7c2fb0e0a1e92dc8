// YAML reader for TeamConfig. Every key is checked: unknown keys, wrong types and bad values
// raise ConfigError with the file, the dotted key path and the line, so typos never pass silently.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "common/core/config_error.h"
#include "common/core/team_config.h"

namespace hexplore::core {
namespace {

class Reader {
 public:
  explicit Reader(std::string origin) : origin_(std::move(origin)) {}

  [[noreturn]] void fail(const YAML::Node& node, const std::string& key, const std::string& problem) const {
    const int line = node.IsDefined() && node.Mark().line >= 0 ? node.Mark().line + 1 : 0;
    throw ConfigError(origin_, key, problem, line);
  }

  // Rejects keys of `map` that are not in `known`.
  void only_keys(const YAML::Node& map, const std::string& path, const std::set<std::string>& known) const {
    if (!map.IsMap()) fail(map, path, "must be a mapping");
    for (const auto& kv : map) {
      // A YAML key may itself be a list or a mapping ("? - a"); a team file's keys are names.
      if (!kv.first.IsScalar()) fail(kv.first, path, "keys must be plain names");
      const auto name = kv.first.as<std::string>();
      if (!known.contains(name)) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        fail(kv.first, join(path, name), "unknown key (known keys: " + list + ")");
      }
    }
  }

  template <typename T>
  void read(const YAML::Node& map, const std::string& path, const std::string& name, T& out) const {
    const YAML::Node node = map[name];
    if (!node.IsDefined() || node.IsNull()) return;  // keep the default
    if (!node.IsScalar()) fail(node, join(path, name), "must be a scalar");
    try {
      out = node.as<T>();
    } catch (const YAML::Exception&) {
      fail(node, join(path, name), "cannot read '" + node.Scalar() + "' as " + type_name<T>());
    }
    if constexpr (std::is_floating_point_v<T>) {
      if (!std::isfinite(out)) fail(node, join(path, name), "must be a finite number");
    }
  }

  void read_vec3(const YAML::Node& map, const std::string& path, const std::string& name, Eigen::Vector3d& out) const {
    const YAML::Node node = map[name];
    if (!node.IsDefined() || node.IsNull()) return;
    if (!node.IsSequence() || node.size() != 3) fail(node, join(path, name), "must be a list of three numbers");
    for (int i = 0; i < 3; ++i) {
      try {
        out[i] = node[i].as<double>();
      } catch (const YAML::Exception&) {
        fail(node[i], join(path, name), "element " + std::to_string(i) + " is not a number");
      }
      if (!std::isfinite(out[i])) fail(node[i], join(path, name), "must be finite numbers");
    }
  }

  static std::string join(const std::string& path, const std::string& name) {
    return path.empty() ? name : path + "." + name;
  }

  const std::string& origin() const { return origin_; }

 private:
  template <typename T>
  static const char* type_name() {
    if constexpr (std::is_same_v<T, bool>) return "a boolean";
    else if constexpr (std::is_integral_v<T>) return "an integer";
    else if constexpr (std::is_floating_point_v<T>) return "a number";
    else return "a string";
  }

  std::string origin_;
};

LidarConfig read_lidar(const Reader& r, const YAML::Node& n, const std::string& path) {
  r.only_keys(n, path, {"name", "lines", "vertical_min_deg", "vertical_max_deg", "horizontal_min_deg",
                        "horizontal_max_deg", "horizontal_step_deg", "min_range_m", "max_range_m",
                        "range_noise_stddev_m", "mount_offset_m", "mount_pitch_deg", "gimbal",
                        "non_repetitive"});
  LidarConfig l;
  r.read(n, path, "name", l.name);
  r.read(n, path, "lines", l.lines);
  r.read(n, path, "vertical_min_deg", l.vertical_min_deg);
  r.read(n, path, "vertical_max_deg", l.vertical_max_deg);
  r.read(n, path, "horizontal_min_deg", l.horizontal_min_deg);
  r.read(n, path, "horizontal_max_deg", l.horizontal_max_deg);
  r.read(n, path, "horizontal_step_deg", l.horizontal_step_deg);
  r.read(n, path, "min_range_m", l.min_range_m);
  r.read(n, path, "max_range_m", l.max_range_m);
  r.read(n, path, "range_noise_stddev_m", l.range_noise_stddev_m);
  r.read_vec3(n, path, "mount_offset_m", l.mount_offset_m);
  r.read(n, path, "mount_pitch_deg", l.mount_pitch_deg);
  r.read(n, path, "gimbal", l.gimbal);
  r.read(n, path, "non_repetitive", l.non_repetitive);
  return l;
}

SpeciesConfig read_species(const Reader& r, const YAML::Node& n, const std::string& path) {
  r.only_keys(n, path, {"name", "builtin", "traversal_level", "max_slope_deg", "max_step_m", "max_roughness_m",
                        "min_clearance_m", "max_sparsity", "speed_mps", "observation_speed_views_per_s",
                        "observation_range_m", "body_half_extents_m", "lidars"});
  SpeciesConfig s;
  std::string builtin;
  r.read(n, path, "builtin", builtin);
  if (!builtin.empty()) {
    const auto known = builtin_species(builtin);
    if (!known) {
      std::string names;
      for (const auto& name : builtin_species_names()) names += (names.empty() ? "" : ", ") + name;
      r.fail(n["builtin"], path + ".builtin", "unknown built-in species '" + builtin + "' (known: " + names + ")");
    }
    s = *known;
  }
  r.read(n, path, "name", s.name);
  r.read(n, path, "traversal_level", s.traversal_level);
  r.read(n, path, "max_slope_deg", s.max_slope_deg);
  r.read(n, path, "max_step_m", s.max_step_m);
  r.read(n, path, "max_roughness_m", s.max_roughness_m);
  r.read(n, path, "min_clearance_m", s.min_clearance_m);
  r.read(n, path, "max_sparsity", s.max_sparsity);
  r.read(n, path, "speed_mps", s.speed_mps);
  r.read(n, path, "observation_speed_views_per_s", s.observation_speed_views_per_s);
  r.read(n, path, "observation_range_m", s.observation_range_m);
  r.read_vec3(n, path, "body_half_extents_m", s.body_half_extents_m);
  if (const auto lidars = n["lidars"]; lidars.IsDefined()) {
    if (!lidars.IsSequence()) r.fail(lidars, path + ".lidars", "must be a list");
    s.lidars.clear();
    for (size_t i = 0; i < lidars.size(); ++i)
      s.lidars.push_back(read_lidar(r, lidars[i], path + ".lidars[" + std::to_string(i) + "]"));
  }
  return s;
}

RobotConfig read_robot(const Reader& r, const YAML::Node& n, const std::string& path) {
  r.only_keys(n, path, {"id", "species", "start", "yaw_deg"});
  RobotConfig robot;
  r.read(n, path, "id", robot.id);
  r.read(n, path, "species", robot.species);
  r.read_vec3(n, path, "start", robot.start_position_m);
  r.read(n, path, "yaw_deg", robot.start_yaw_deg);
  return robot;
}

void read_radio(const Reader& r, const YAML::Node& n, RadioConfig& radio) {
  const std::string path = "transport.radio";
  r.only_keys(n, path, {"bandwidth_bytes_per_s", "latency_s", "loss", "range_m", "max_queue_age_s", "outages"});
  if (const auto list = n["outages"]; list.IsDefined() && !list.IsNull()) {
    if (!list.IsSequence()) r.fail(list, path + ".outages", "must be a list of {robot, from_s, to_s}");
    for (size_t i = 0; i < list.size(); ++i) {
      const std::string at = path + ".outages[" + std::to_string(i) + "]";
      if (!list[i].IsMap()) r.fail(list[i], at, "must be a map {robot, from_s, to_s}");
      r.only_keys(list[i], at, {"robot", "from_s", "to_s"});
      RadioOutage outage;
      r.read(list[i], at, "robot", outage.robot);
      r.read(list[i], at, "from_s", outage.from_s);
      r.read(list[i], at, "to_s", outage.to_s);
      if (outage.robot.empty()) r.fail(list[i], at + ".robot", "names the robot cut off");
      if (!(outage.from_s >= 0.0) || !(outage.to_s > outage.from_s) || !std::isfinite(outage.to_s))
        r.fail(list[i], at + ".to_s", "must satisfy 0 <= from_s < to_s (sim seconds)");
      radio.outages.push_back(outage);
    }
  }
  r.read(n, path, "bandwidth_bytes_per_s", radio.bandwidth_bytes_per_s);
  r.read(n, path, "latency_s", radio.latency_s);
  r.read(n, path, "loss", radio.loss);
  r.read(n, path, "range_m", radio.range_m);
  r.read(n, path, "max_queue_age_s", radio.max_queue_age_s);
  auto check = [&](const char* key, bool ok, const char* problem) {
    if (!ok) r.fail(n[key], path + "." + key, problem);
  };
  check("bandwidth_bytes_per_s", radio.bandwidth_bytes_per_s >= 0.0, "must be >= 0 (0 = unlimited)");
  check("latency_s", radio.latency_s >= 0.0 && radio.latency_s <= 60.0, "must be in [0, 60] seconds");
  check("loss", radio.loss >= 0.0 && radio.loss < 1.0, "must be in [0, 1)");
  check("range_m", radio.range_m >= 0.0, "must be >= 0 (0 = unlimited)");
  check("max_queue_age_s", radio.max_queue_age_s > 0.0 && radio.max_queue_age_s <= 600.0, "must be in (0, 600] seconds");
}

void read_transport(const Reader& r, const YAML::Node& n, TransportConfig& t) {
  const std::string path = "transport";
  r.only_keys(n, path, {"scheme", "host_template", "base_port", "ports_per_robot", "ipc_dir", "send_high_water_mark",
                        "receive_high_water_mark", "max_message_bytes", "linger_ms", "curve_keys_dir", "radio"});
  if (const auto radio = n["radio"]; radio.IsDefined() && !radio.IsNull()) read_radio(r, radio, t.radio);
  r.read(n, path, "scheme", t.scheme);
  r.read(n, path, "host_template", t.host_template);
  r.read(n, path, "base_port", t.base_port);
  r.read(n, path, "ports_per_robot", t.ports_per_robot);
  r.read(n, path, "ipc_dir", t.ipc_dir);
  r.read(n, path, "send_high_water_mark", t.send_high_water_mark);
  r.read(n, path, "receive_high_water_mark", t.receive_high_water_mark);
  r.read(n, path, "max_message_bytes", t.max_message_bytes);
  r.read(n, path, "linger_ms", t.linger_ms);
  r.read(n, path, "curve_keys_dir", t.curve_keys_dir);
}

void read_liveness(const Reader& r, const YAML::Node& n, LivenessParams& l) {
  const std::string path = "params.liveness";
  r.only_keys(n, path, {"planning_team_s", "obstacle_s", "body_filter_s", "sim_body_s", "station_s"});
  auto read_positive = [&](const char* key, double& out) {
    r.read(n, path, key, out);
    if (!(out > 0.0) || !std::isfinite(out)) r.fail(n[key], path + "." + key, "must be a positive number of seconds");
  };
  read_positive("planning_team_s", l.planning_team_s);
  read_positive("obstacle_s", l.obstacle_s);
  read_positive("body_filter_s", l.body_filter_s);
  read_positive("sim_body_s", l.sim_body_s);
  read_positive("station_s", l.station_s);
}

void read_params(const Reader& r, const YAML::Node& n, AlgorithmParams& p) {
  const std::string path = "params";
  r.only_keys(n, path, {"map_resolution_m", "rho_th", "rho_measure", "min_ise_patch_voxels", "gamma_th_deg", "gamma_th_ground_deg", "s_th_deg", "theta_l_deg", "theta_u_deg", "shared_view_angle_margin_deg",
                        "task_view_choice", "cluster_work", "beta_i", "beta_l", "beta_zeta", "beta_varsigma", "beta_e", "beta_c", "beta_m", "beta_d",
                        "reference_window", "eta_e_m", "eta_s_m", "eta_c_s", "eta_r_m", "eta_p_m", "eta_t_s", "liveness", "ga_population",
                        "ga_max_generations", "ga_time_budget_s", "planner", "seed", "planner_seed"});
  r.read(n, path, "map_resolution_m", p.map_resolution_m);
  r.read(n, path, "rho_th", p.rho_th);
  r.read(n, path, "rho_measure", p.rho_measure);
  if (p.rho_measure != "all_points" && p.rho_measure != "qualifying_points" && p.rho_measure != "neighbour_occupancy" &&
      p.rho_measure != "fused_surface")
    r.fail(n["rho_measure"], path + ".rho_measure",
           "must be all_points, qualifying_points, neighbour_occupancy or fused_surface, got '" + p.rho_measure + "'");
  r.read(n, path, "min_ise_patch_voxels", p.min_ise_patch_voxels);
  if (p.min_ise_patch_voxels < 1)
    r.fail(n["min_ise_patch_voxels"], path + ".min_ise_patch_voxels",
           "must be >= 1, got " + std::to_string(p.min_ise_patch_voxels));
  r.read(n, path, "gamma_th_deg", p.gamma_th_deg);
  r.read(n, path, "gamma_th_ground_deg", p.gamma_th_ground_deg);
  r.read(n, path, "s_th_deg", p.s_th_deg);
  r.read(n, path, "theta_l_deg", p.theta_l_deg);
  r.read(n, path, "theta_u_deg", p.theta_u_deg);
  r.read(n, path, "shared_view_angle_margin_deg", p.shared_view_angle_margin_deg);
  r.read(n, path, "task_view_choice", p.task_view_choice);
  if (p.task_view_choice != "weakest_species" && p.task_view_choice != "best_score")
    r.fail(n["task_view_choice"], path + ".task_view_choice",
           "must be weakest_species or best_score, got '" + p.task_view_choice + "'");
  r.read(n, path, "cluster_work", p.cluster_work);
  if (p.cluster_work != "cover" && p.cluster_work != "every_view")
    r.fail(n["cluster_work"], path + ".cluster_work", "must be cover or every_view, got '" + p.cluster_work + "'");
  r.read(n, path, "beta_i", p.beta_i);
  r.read(n, path, "beta_l", p.beta_l);
  r.read(n, path, "beta_zeta", p.beta_zeta);
  r.read(n, path, "beta_varsigma", p.beta_varsigma);
  r.read(n, path, "beta_e", p.beta_e);
  r.read(n, path, "beta_c", p.beta_c);
  r.read(n, path, "beta_m", p.beta_m);
  r.read(n, path, "beta_d", p.beta_d);
  r.read(n, path, "reference_window", p.reference_window);
  if (p.reference_window < -1)
    r.fail(n["reference_window"], path + ".reference_window",
           "must be >= 0, or -1 for every segment, got " + std::to_string(p.reference_window));
  r.read(n, path, "eta_e_m", p.eta_e_m);
  r.read(n, path, "eta_s_m", p.eta_s_m);
  r.read(n, path, "eta_c_s", p.eta_c_s);
  r.read(n, path, "eta_r_m", p.eta_r_m);
  r.read(n, path, "eta_p_m", p.eta_p_m);
  r.read(n, path, "eta_t_s", p.eta_t_s);
  if (const auto l = n["liveness"]; l.IsDefined()) read_liveness(r, l, p.liveness);
  r.read(n, path, "ga_population", p.ga_population);
  r.read(n, path, "ga_max_generations", p.ga_max_generations);
  r.read(n, path, "ga_time_budget_s", p.ga_time_budget_s);
  r.read(n, path, "planner", p.planner);
  r.read(n, path, "seed", p.seed);
  r.read(n, path, "planner_seed", p.planner_seed);
}

}  // namespace

namespace {

TeamConfig parse_root(const std::string& yaml_text, const std::string& origin) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    throw ConfigError(origin, "", "YAML syntax error: " + e.msg, e.mark.line + 1);
  }
  Reader r(origin);
  if (!root.IsMap()) throw ConfigError(origin, "", "the team file must be a YAML mapping");
  r.only_keys(root, "", {"scene", "scene_import", "time_limit_s", "metrics_base_port", "exploration_region", "species",
                         "robots", "transport", "params"});
  TeamConfig c;
  c.source_file = origin;
  r.read(root, "", "scene", c.scene);
  r.read(root, "", "time_limit_s", c.time_limit_s);
  if (const auto import = root["scene_import"]; import.IsDefined()) {
    r.only_keys(import, "scene_import", {"up_axis", "scale", "yaw_deg", "translation"});
    r.read(import, "scene_import", "up_axis", c.scene_import.up_axis);
    r.read(import, "scene_import", "scale", c.scene_import.scale);
    r.read(import, "scene_import", "yaw_deg", c.scene_import.yaw_deg);
    r.read_vec3(import, "scene_import", "translation", c.scene_import.translation_m);
    if (c.scene_import.up_axis != "z" && c.scene_import.up_axis != "y")
      r.fail(import["up_axis"], "scene_import.up_axis", "must be z or y, got '" + c.scene_import.up_axis + "'");
    if (!(c.scene_import.scale > 0.0)) r.fail(import["scale"], "scene_import.scale", "must be > 0");
    if (std::abs(c.scene_import.yaw_deg) > 360.0)
      r.fail(import["yaw_deg"], "scene_import.yaw_deg", "must be within [-360, 360]");
  }
  r.read(root, "", "metrics_base_port", c.metrics_base_port);
  if (const auto region = root["exploration_region"]; region.IsDefined()) {
    r.only_keys(region, "exploration_region", {"min", "max"});
    Eigen::Vector3d lo = c.exploration_region.min(), hi = c.exploration_region.max();
    r.read_vec3(region, "exploration_region", "min", lo);
    r.read_vec3(region, "exploration_region", "max", hi);
    if ((hi.array() <= lo.array()).any()) r.fail(region, "exploration_region", "max must exceed min on every axis");
    c.exploration_region = Eigen::AlignedBox3d(lo, hi);
  }
  const auto species = root["species"];
  if (!species.IsDefined() || !species.IsSequence()) r.fail(species.IsDefined() ? species : root, "species", "must be a list of species");
  for (size_t i = 0; i < species.size(); ++i)
    c.species.push_back(read_species(r, species[i], "species[" + std::to_string(i) + "]"));
  const auto robots = root["robots"];
  if (!robots.IsDefined() || !robots.IsSequence()) r.fail(robots.IsDefined() ? robots : root, "robots", "must be a list of robots");
  for (size_t i = 0; i < robots.size(); ++i)
    c.robots.push_back(read_robot(r, robots[i], "robots[" + std::to_string(i) + "]"));
  if (const auto t = root["transport"]; t.IsDefined()) read_transport(r, t, c.transport);
  if (const auto p = root["params"]; p.IsDefined()) read_params(r, p, c.params);
  validate(c);
  return c;
}

}  // namespace

TeamConfig parse_team_config(const std::string& yaml_text, const std::string& origin) {
  try {
    return parse_root(yaml_text, origin);
  } catch (const YAML::Exception& e) {
    // The reader checks every node before converting it; this is the net for a shape it did
    // not foresee (tests/fuzz/fuzz_team_yaml), so a broken file still ends in a ConfigError.
    throw ConfigError(origin, "", "cannot read the file: " + e.msg, e.mark.is_null() ? 0 : e.mark.line + 1);
  }
}

TeamConfig load_team_config(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path, "", "cannot open the file (missing or unreadable)");
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (buffer.str().find_first_not_of(" \t\r\n") == std::string::npos) throw ConfigError(path, "", "the file is empty");
  TeamConfig config = parse_team_config(buffer.str(), path);
  // A relative key folder belongs to the team file, wherever the process was started from.
  std::string& keys = config.transport.curve_keys_dir;
  if (!keys.empty() && std::filesystem::path(keys).is_relative())
    keys = (std::filesystem::path(path).parent_path() / keys).lexically_normal().string();
  return config;
}

}  // namespace hexplore::core
