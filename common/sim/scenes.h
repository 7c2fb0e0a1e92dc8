#pragma once
// The simulated worlds: the built-in procedural scenes (deterministic per seed) and meshes
// loaded from files. Frame: z up, ground at z = 0, metres.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "common/core/team_config.h"
#include "common/sim/mesh_io.h"
#include "common/sim/triangle_mesh.h"

namespace hexplore::sim {

struct SceneInfo {
  std::string name;                            // built-in name or the mesh path
  TriangleMesh mesh;
  Eigen::AlignedBox3d site;                    // region the evaluation counts (ground truth is cropped to it)
  std::vector<Eigen::Vector3d> suggested_starts;  // free flat ground where robots can be spawned
};

// Names of the built-in scenes: single-building, small-building, multi-building, corridor-stairs, office,
// multi-storey, campus.
std::vector<std::string> scene_names();
bool is_builtin_scene(const std::string& name);

// Generates a built-in scene. Throws SceneError listing the known names for another name.
SceneInfo generate_scene(const std::string& name, uint64_t seed);

// A built-in name generates that scene; anything else is a mesh path loaded with `options`
// (site = the mesh bounds, no suggested starts).
SceneInfo load_scene(const std::string& name_or_path, uint64_t seed, const MeshImportOptions& options = {});

// The scene a team file names, ready for load_scene: built-in names unchanged; a relative
// mesh path is taken relative to the team file's folder when a file exists there.
std::string resolve_scene(const std::string& scene, const std::string& team_file);

// The team's world: its scene resolved against the team file and placed with the team file's
// scene_import options. What the sim simulates and the station evaluates. Throws SceneError.
SceneInfo load_team_scene(const core::TeamConfig& team);

}  // namespace hexplore::sim
