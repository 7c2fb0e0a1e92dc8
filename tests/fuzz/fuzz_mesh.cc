// A scene file as the simulator and the station load it (sim::load_mesh: assimp, then the
// checks for an empty or triangle-free mesh). A broken file must end in sim::SceneError, never
// in a crash or another exception. Input: byte 0 picks the format (PLY, OBJ, STL), the rest is
// the file, written where load_mesh can open it by name (as hexplore calls it).

#include <unistd.h>

#include <cstdio>
#include <string>

#include "common/sim/mesh_io.h"
#include "common/sim/scene_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hexplore;
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".ply", ".obj", ".stl"};
  const std::string dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  const std::string path = dir + "/hexplore_fuzz_mesh_" + std::to_string(getpid()) + kExtensions[data[0] % 3];
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data + 1, 1, size - 1, f);
    std::fclose(f);
  } else {
    return 0;
  }
  try {
    sim::load_mesh(path);
  } catch (const sim::SceneError&) {
  }
  std::remove(path.c_str());
  return 0;
}
