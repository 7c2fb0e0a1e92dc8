#include "common/sim/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "common/sim/scene_error.h"

namespace hexplore::sim {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

void collect(const aiScene& scene, TriangleMesh& out) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    if (!(mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    const auto base = static_cast<uint32_t>(out.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v)
      out.vertices.emplace_back(mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z);
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no surface
      out.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
    }
  }
}

}  // namespace

UpAxis parse_up_axis(const std::string& text, const std::string& origin) {
  const std::string t = lower(text);
  if (t == "z") return UpAxis::kZ;
  if (t == "y") return UpAxis::kY;
  throw SceneError(origin, "up axis must be 'z' or 'y' (got '" + text + "')");
}

TriangleMesh load_mesh(const std::string& path, const MeshImportOptions& options) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw SceneError(path, "mesh file does not exist");
  if (!fs::is_regular_file(path, ec)) throw SceneError(path, "not a regular file");
  if (fs::file_size(path, ec) == 0) throw SceneError(path, "mesh file is empty");
  if (!(options.scale > 0.0) || !std::isfinite(options.scale))
    throw SceneError(path, "import scale must be a positive number");

  Assimp::Importer importer;
  // Points and lines are dropped; node transforms baked so a multi-part file keeps its layout.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                aiProcess_SortByPType);
  if (scene == nullptr) {
    const std::string why = importer.GetErrorString();
    throw SceneError(path, "malformed or unsupported mesh: " + (why.empty() ? std::string("unknown error") : why));
  }
  TriangleMesh mesh;
  collect(*scene, mesh);
  if (mesh.empty()) throw SceneError(path, "mesh contains no triangles");
  for (const auto& v : mesh.vertices)
    if (!v.allFinite()) throw SceneError(path, "mesh contains non-finite vertex coordinates");

  Eigen::Affine3f t = Eigen::Affine3f::Identity();
  t.translate(options.translation_m.cast<float>());
  t.rotate(Eigen::AngleAxisf(static_cast<float>(options.yaw_deg * M_PI / 180.0), Eigen::Vector3f::UnitZ()));
  t.scale(static_cast<float>(options.scale));
  if (options.up_axis == UpAxis::kY) {
    Eigen::Matrix3f y_to_z;
    y_to_z << 1, 0, 0, 0, 0, -1, 0, 1, 0;  // (x, y, z) <- (x, -z, y)
    t.rotate(y_to_z);
  }
  mesh.transform(t);
  mesh.drop_degenerate();
  if (mesh.empty()) throw SceneError(path, "mesh has only degenerate (zero-area) triangles");
  return mesh;
}

void write_mesh(const TriangleMesh& mesh, const std::string& path) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  if (ext != ".ply" && ext != ".obj") throw SceneError(path, "can only write .ply or .obj meshes");
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw SceneError(path, "cannot open for writing");
  if (ext == ".ply") {
    out << "ply\nformat binary_little_endian 1.0\ncomment hexplore scene\n"
        << "element vertex " << mesh.vertices.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "element face " << mesh.triangles.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
    for (const auto& v : mesh.vertices) out.write(reinterpret_cast<const char*>(v.data()), 12);
    for (const auto& t : mesh.triangles) {
      const unsigned char n = 3;
      out.write(reinterpret_cast<const char*>(&n), 1);
      out.write(reinterpret_cast<const char*>(t.data()), 12);
    }
  } else {
    out << "# hexplore scene\n";
    out.precision(7);
    for (const auto& v : mesh.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
  if (!out) throw SceneError(path, "write failed");
}

}  // namespace hexplore::sim
