#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "tools/mtsp_solver/cli.h"
#include "tools/mtsp_solver/species_file.h"
#include "tests/support/scratch_dir.h"

namespace hexplore::mtsp {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  static const hexplore::testing::ScratchDir dir("mtsp_cli_test");  // removed when the binary exits
  const std::string path = dir.file(name);
  std::ofstream(path) << text;
  return path;
}

const char* kTsp =
    "NAME : tiny\nTYPE : TSP\nDIMENSION : 7\nEDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n"
    "1 0 0\n2 10 0\n3 20 0\n4 -10 0\n5 -20 0\n6 0 30\n7 0 40\nEOF\n";

TEST(MtspCli, SolvesAndPrintsRoutes) {
  const std::string tsp = write_temp("tiny.tsp", kTsp);
  const std::string species = write_temp("tiny.species", "# two species\nsalesman 1 wheeled\nsalesman 2 tracked\ncity 6 tracked\ncity 7 tracked\n");
  const CliOptions o = parse_cli({tsp, "-m", "2", "--open", "--species", species, "--generations", "300", "--time-limit", "0", "--objective", "min-max"});
  std::ostringstream out, err;
  ASSERT_EQ(run_cli(o, out, err), 0) << err.str();
  // The tracked salesman must take the private cities 6 and 7, so the wheeled one takes the
  // line; min-max then leaves salesman 2 with 0 -> 30 -> 40 (40) and salesman 1 with 60.
  EXPECT_NE(out.str().find("salesman 2 [tracked] cost 40: 1 6 7"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("longest 60"), std::string::npos) << out.str();
  // Same seed, same output (generation budget only).
  std::ostringstream again;
  run_cli(o, again, err);
  EXPECT_EQ(out.str().substr(0, out.str().find("generations")), again.str().substr(0, again.str().find("generations")));
}

TEST(MtspCli, ReportsBadInputWithLineNumbers) {
  const std::string bad = write_temp("bad.tsp", "NAME : bad\nDIMENSION : 2\nEDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n1 0 0\n2 x y\n");
  std::ostringstream out, err;
  EXPECT_EQ(run_cli(parse_cli({bad, "--generations", "1"}), out, err), 2);
  EXPECT_NE(err.str().find("bad.tsp:6: expected '<node id> <x> <y>'"), std::string::npos) << err.str();

  std::istringstream species("salesman 1 a\ncity 99 a\n");
  try {
    parse_species_file(species, "s.txt", 2, 7);
    FAIL() << "no error";
  } catch (const SpeciesFileError& e) {
    EXPECT_STREQ(e.what(), "s.txt:2: city 99 outside 1..7");
  }
  EXPECT_THROW(parse_cli({"x.tsp", "--objective", "fastest"}), std::invalid_argument);
  EXPECT_THROW(parse_cli({"x.tsp", "--bogus"}), std::invalid_argument);
  EXPECT_THROW(parse_cli({}), std::invalid_argument);
}

}  // namespace
}  // namespace hexplore::mtsp
