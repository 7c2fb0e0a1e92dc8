// The TSPLIB reader behind hexplore_mtsp and bench_mtsp_quality. A broken file must end in
// planning::TsplibError (file and line), never in a crash or another exception.

#include <sstream>
#include <string>

#include "common/planning/mtsp/tsplib.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hexplore;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    planning::parse_tsplib(in, "fuzz.tsp");
  } catch (const planning::TsplibError&) {
  }
  return 0;
}
