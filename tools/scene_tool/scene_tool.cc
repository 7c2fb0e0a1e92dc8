// hexplore_scene: generates a built-in scene from a seed (or loads a mesh file) and prints
// its statistics; --out writes the mesh (.ply or .obj) into a folder created on demand.
//
//   hexplore_scene --scene single-building --seed 1 --out scenes/
//   hexplore_scene --scene my_site.dae --up y --scale 0.0254
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include "common/sim/mesh_io.h"
#include "common/sim/scene_error.h"
#include "common/sim/scenes.h"

namespace {

void usage() {
  std::cerr << "usage: hexplore_scene --scene NAME|MESH [--seed N] [--out DIR|FILE.ply|FILE.obj]\n"
               "                      [--up z|y] [--scale S] [--yaw-deg D]\n"
               "built-in scenes:";
  for (const auto& n : hexplore::sim::scene_names()) std::cerr << ' ' << n;
  std::cerr << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  using namespace hexplore::sim;
  std::string scene, out;
  uint64_t seed = 1;
  MeshImportOptions import;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    try {
      if (a == "--scene") scene = value();
      else if (a == "--seed") seed = std::stoull(value());
      else if (a == "--out") out = value();
      else if (a == "--up") import.up_axis = parse_up_axis(value(), "--up");
      else if (a == "--scale") import.scale = std::stod(value());
      else if (a == "--yaw-deg") import.yaw_deg = std::stod(value());
      else if (a == "-h" || a == "--help") {
        usage();
        return 0;
      } else {
        std::cerr << "unknown argument '" << a << "'\n";
        usage();
        return 2;
      }
    } catch (const std::exception& e) {
      std::cerr << "bad value for " << a << ": " << e.what() << '\n';
      return 2;
    }
  }
  if (scene.empty()) {
    usage();
    return 2;
  }
  try {
    const SceneInfo info = load_scene(scene, seed, import);
    const auto b = info.mesh.bounds();
    const Eigen::Vector3d site = info.site.sizes();
    std::printf("scene        %s (seed %llu)\n", info.name.c_str(), static_cast<unsigned long long>(seed));
    std::printf("triangles    %zu\nvertices     %zu\n", info.mesh.triangle_count(), info.mesh.vertices.size());
    std::printf("surface area %.1f m2\n", info.mesh.surface_area());
    std::printf("bbox         (%.2f, %.2f, %.2f) .. (%.2f, %.2f, %.2f)\n", b.min().x(), b.min().y(), b.min().z(),
                b.max().x(), b.max().y(), b.max().z());
    std::printf("site         %.1f x %.1f m (%.0f m2)\n", site.x(), site.y(), site.x() * site.y());
    std::printf("hash         %016llx\n", static_cast<unsigned long long>(info.mesh.content_hash()));
    for (const auto& s : info.suggested_starts) std::printf("start        (%.1f, %.1f, %.1f)\n", s.x(), s.y(), s.z());
    if (!out.empty()) {
      std::filesystem::path path(out);
      if (path.extension() != ".ply" && path.extension() != ".obj") {
        std::filesystem::create_directories(path);
        const std::string stem = is_builtin_scene(scene) ? scene + "_seed" + std::to_string(seed)
                                                         : std::filesystem::path(scene).stem().string();
        path /= stem + ".ply";
      } else if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path());
      }
      write_mesh(info.mesh, path.string());
      std::printf("written      %s\n", path.c_str());
    }
  } catch (const SceneError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
