#pragma once
// Topic names. Topics are hierarchical '/'-separated strings; a subscription is a prefix, so
// "team/" receives every team topic and "robot/r1/" every topic of robot r1. Robot-local
// topics are robot/<id>/<leaf>; team topics (team/<leaf>) are the only ones that cross robots.

#include <string>
#include <string_view>

namespace hexplore::transport::topics {

// Leaves of robot-local topics.
inline constexpr std::string_view kScan = "scan";        // ScanFrame        sim -> mapping
inline constexpr std::string_view kPose = "pose";        // RobotPose        sim -> mapping, planning, safety
inline constexpr std::string_view kVoxels = "voxels";    // VoxelDelta       mapping -> hlmap
inline constexpr std::string_view kHlmap = "hlmap";      // FusedMapUpdate   hlmap -> planning
inline constexpr std::string_view kRoute = "route";      // ExplorationRoute planning -> safety
inline constexpr std::string_view kPath = "path";        // ExecutablePath   planning -> safety
inline constexpr std::string_view kMotion = "motion";    // MotionCommand    safety -> sim
inline constexpr std::string_view kStatus = "status";    // ServiceStatus    every service

// Team topics.
inline constexpr std::string_view kTeamPrefix = "team/";
inline constexpr std::string_view kTeamPose = "team/pose";        // RobotPose      sim -> teammates
inline constexpr std::string_view kTeamMap = "team/map";          // MapIncrement   hlmap -> peers' hlmap
inline constexpr std::string_view kTeamPlan = "team/plan";        // TeamSolution   planning -> peers' planning
inline constexpr std::string_view kTeamPath = "team/path";        // PathFragment   safety -> peers' safety
inline constexpr std::string_view kTeamMission = "team/mission";  // MissionCommand station -> everyone

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
