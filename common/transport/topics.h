#pragma once
// Topic names. Topics are hierarchical '/'-separated strings; a subscription is a prefix, so
// "team/" receives every team topic and "robot/r1/" every topic of robot r1. Robot-local
// topics are robot/<id>/<leaf>; team topics (team/<leaf>) are the only ones that cross robots.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hexplore::transport::topics {

// Leaves of robot-local topics.
inline constexpr std::string_view kScan = "scan";        // ScanFrame        sim -> mapping
inline constexpr std::string_view kPose = "pose";        // RobotPose        sim -> mapping, planning, safety
inline constexpr std::string_view kVoxels = "voxels";    // VoxelDelta       mapping -> hlmap
inline constexpr std::string_view kHlmap = "hlmap";      // FusedMapUpdate   hlmap -> planning
inline constexpr std::string_view kRoute = "route";      // ExplorationRoute planning -> observers (tests, tools; no service reads it)
inline constexpr std::string_view kPath = "path";        // ExecutablePath   planning -> safety
inline constexpr std::string_view kMotion = "motion";    // MotionCommand    safety -> sim
inline constexpr std::string_view kStatus = "status";    // ServiceStatus    every service

// The simulated world: each sim shares its robot's true body with the other sims at the motion
// rate, so that teammates are solid and visible to its LiDARs. It stands for physics, which
// hardware gets for free: no robot service reads it, and it is not radio traffic.
inline constexpr std::string_view kSimBody = "sim/body";  // RobotPose      sim -> other sims

// Team topics.
inline constexpr std::string_view kTeamPrefix = "team/";
inline constexpr std::string_view kTeamPose = "team/pose";        // RobotPose      sim -> teammates (dead-reckoned)
inline constexpr std::string_view kTeamMap = "team/map";          // MapIncrement   hlmap -> peers' hlmap
inline constexpr std::string_view kTeamPlan = "team/plan";        // TeamSolution   planning -> peers' planning
inline constexpr std::string_view kTeamPath = "team/path";        // PathFragment   safety -> peers' safety (on change)
inline constexpr std::string_view kTeamMission = "team/mission";  // MissionCommand station -> everyone

// Team topics cross robots: what the paper's communication tables count and what the radio
// model (link_model.h) applies to.
bool is_team_topic(std::string_view topic);

// On the wire every team topic above travels as a one-byte code instead of its name (the name
// alone would outweigh a compact pose). Codes are control bytes, which no valid topic starts
// with, so they never collide with a named topic; other topics go by name.
std::string_view wire_topic(std::string_view topic);
// The topic a received first frame stands for: the name of a code, else the frame itself;
// nullopt for a control byte that is no known code.
std::optional<std::string_view> topic_from_wire(std::string_view wire);
// The ZeroMQ subscriptions a prefix needs: the prefix itself plus the code of every coded
// topic it covers ("team/" -> "team/" and five codes).
std::vector<std::string> wire_prefixes(std::string_view prefix);

// "robot/<id>/<leaf>".
std::string robot_topic(std::string_view robot_id, std::string_view leaf);
// "robot/<id>/": prefix of every topic of one robot.
std::string robot_prefix(std::string_view robot_id);

// Shorthands for the robot-local topics.
inline std::string scan(std::string_view id) { return robot_topic(id, kScan); }
inline std::string pose(std::string_view id) { return robot_topic(id, kPose); }
inline std::string voxels(std::string_view id) { return robot_topic(id, kVoxels); }
inline std::string hlmap(std::string_view id) { return robot_topic(id, kHlmap); }
inline std::string route(std::string_view id) { return robot_topic(id, kRoute); }
inline std::string path(std::string_view id) { return robot_topic(id, kPath); }
inline std::string motion(std::string_view id) { return robot_topic(id, kMotion); }
inline std::string status(std::string_view id) { return robot_topic(id, kStatus); }

// A valid topic: 1..128 characters from [A-Za-z0-9_.-] and '/', no empty segment except a
// trailing '/' (which only prefixes may have).
bool is_valid_topic(std::string_view topic);
bool is_valid_prefix(std::string_view prefix);
// Whether `topic` is covered by subscription `prefix` (plain byte prefix, as ZeroMQ filters).
bool matches(std::string_view prefix, std::string_view topic);
// The metric label for a topic: the topic itself when valid, else "invalid" (a malformed
// frame must not create an unbounded number of label values).
std::string_view topic_label(std::string_view topic);
// The metric label for a peer robot id: the id when it looks like one, else "unknown".
std::string_view peer_label(std::string_view robot_id);

}  // namespace hexplore::transport::topics
