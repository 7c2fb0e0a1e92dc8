#include "common/sim/mesh_io.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "common/sim/mesh_builder.h"
#include "common/sim/scene_error.h"
#include "tests/support/scratch_dir.h"

namespace hexplore::sim {
namespace {

std::string temp_path(const std::string& name) {
  static const hexplore::testing::ScratchDir dir("hexplore_sim_test");
  return dir.file(name);
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

void expect_scene_error(const std::string& path, const std::string& fragment) {
  try {
    load_mesh(path);
    FAIL() << "expected a SceneError for " << path;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.source(), path);
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(MeshIo, MissingFileIsRejectedNamingIt) { expect_scene_error(temp_path("does_not_exist.ply"), "does not exist"); }

TEST(MeshIo, EmptyFileIsRejected) {
  const auto p = temp_path("empty.obj");
  write_text(p, "");
  expect_scene_error(p, "empty");
}

TEST(MeshIo, GarbageIsRejected) {
  const auto p = temp_path("garbage.ply");
  write_text(p, "this is not a mesh \x01\x02\x03 at all\n");
  expect_scene_error(p, "malformed");
}

TEST(MeshIo, FileWithoutTrianglesIsRejected) {
  const auto p = temp_path("points.obj");
  write_text(p, "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_THROW(load_mesh(p), SceneError);
}

TEST(MeshIo, RoundTripPlyAndObjKeepGeometry) {
  MeshBuilder b;
  b.box({0, 0, 0}, {1, 2, 3});
  const TriangleMesh box = b.take();
  for (const char* ext : {".ply", ".obj"}) {
    const auto p = temp_path(std::string("box") + ext);
    write_mesh(box, p);
    const TriangleMesh back = load_mesh(p);
    EXPECT_EQ(back.triangle_count(), 12u) << ext;
    EXPECT_NEAR(back.surface_area(), box.surface_area(), 1e-4) << ext;
    EXPECT_TRUE(back.bounds().isApprox(box.bounds())) << ext;
  }
}

TEST(MeshIo, UpAxisAndScaleAreApplied) {
  MeshBuilder b;
  b.box({0, 0, 0}, {1, 2, 3});  // read back as if y were up
  const auto p = temp_path("yup.ply");
  write_mesh(b.take(), p);
  MeshImportOptions o;
  o.up_axis = UpAxis::kY;
  o.scale = 2.0;
  const auto bounds = load_mesh(p, o).bounds();
  // (x, y, z) <- (x, -z, y), then doubled: x in [0, 2], y in [-6, 0], z in [0, 4].
  EXPECT_NEAR(bounds.min().y(), -6.0, 1e-5);
  EXPECT_NEAR(bounds.max().z(), 4.0, 1e-5);
  EXPECT_NEAR(bounds.max().x(), 2.0, 1e-5);
  EXPECT_THROW(parse_up_axis("x", "test"), SceneError);
}

TEST(MeshIo, WriteRejectsUnknownExtension) {
  MeshBuilder b;
  b.box({0, 0, 0}, {1, 1, 1});
  EXPECT_THROW(write_mesh(b.mesh(), temp_path("box.stl")), SceneError);
}

}  // namespace
}  // namespace hexplore::sim
