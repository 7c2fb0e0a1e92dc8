#pragma once
// Reading and writing triangle meshes. Reading goes through assimp (OBJ, PLY, STL, COLLADA
// and the other formats it knows); writing produces PLY (binary) or OBJ (text).
//
// Other users' scenes: set `scale` for units (0.001 for millimetres, 0.0254 for inches when
// the importer does not apply the file's own unit), `up_axis` = kY for Y-up files (most
// COLLADA/glTF exports after assimp's conversion, Blender OBJ defaults) and an optional
// placement. Non-watertight and inconsistently wound meshes are accepted as they are: all
// ray casting is two-sided.

#include <string>

#include <Eigen/Core>

#include "common/sim/triangle_mesh.h"

namespace hexplore::sim {

enum class UpAxis { kZ, kY };

struct MeshImportOptions {
  double scale = 1.0;                 // multiplies coordinates after the up-axis change
  UpAxis up_axis = UpAxis::kZ;        // kY: (x, y, z) <- (x, -z, y)
  double yaw_deg = 0.0;               // rotation about z applied after scaling
  Eigen::Vector3d translation_m = Eigen::Vector3d::Zero();  // applied last
};

// Parses "z"/"y" (case-insensitive); throws SceneError naming `origin` otherwise.
UpAxis parse_up_axis(const std::string& text, const std::string& origin);

// Loads every triangle of the file (node transforms baked in). Throws SceneError naming the
// file and the problem for a missing, empty, malformed or triangle-free file.
TriangleMesh load_mesh(const std::string& path, const MeshImportOptions& options = {});

// Writes PLY (binary little-endian) or OBJ chosen by the extension; throws SceneError for
// another extension or an I/O failure.
void write_mesh(const TriangleMesh& mesh, const std::string& path);

}  // namespace hexplore::sim
