#include "common/planning/mtsp/tsplib.h"

#include <sstream>

#include <gtest/gtest.h>

namespace hexplore::planning {
namespace {

TsplibInstance parse(const std::string& text) {
  std::istringstream in(text);
  return parse_tsplib(in, "test.tsp");
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const TsplibError& e) {
    return e.what();
  }
  return "";
}

const char* kSquare =
    "NAME : square\n"
    "COMMENT : four nodes\n"
    "TYPE : TSP\n"
    "DIMENSION : 4\n"
    "EDGE_WEIGHT_TYPE : EUC_2D\n"
    "NODE_COORD_SECTION\n"
    "1 0 0\n"
    "2 3 4\n"
    "3 3.4 0\n"
    "4 0 2.5\n"
    "EOF\n";

TEST(Tsplib, ParsesCoordinatesAndRoundsLikeTsplib) {
  const TsplibInstance t = parse(kSquare);
  EXPECT_EQ(t.name, "square");
  ASSERT_EQ(t.dimension(), 4);
  EXPECT_EQ(tsplib_distance(t, 0, 1), 5.0);
  EXPECT_EQ(tsplib_distance(t, 0, 2), 3.0);     // nint(3.4)
  EXPECT_EQ(tsplib_distance(t, 0, 3), 3.0);     // nint(2.5) rounds half up
  EXPECT_NEAR(tsplib_distance(t, 0, 2, false), 3.4, 1e-12);
}

TEST(Tsplib, AttPseudoEuclidean) {
  const TsplibInstance t = parse("NAME: a\nTYPE: TSP\nDIMENSION: 2\nEDGE_WEIGHT_TYPE: ATT\nNODE_COORD_SECTION\n1 0 0\n2 30 40\nEOF\n");
  // r = sqrt(2500 / 10) = 15.81.., nint = 16 >= r -> 16
  EXPECT_EQ(tsplib_distance(t, 0, 1), 16.0);
  const TsplibInstance u = parse("NAME: a\nTYPE: TSP\nDIMENSION: 2\nEDGE_WEIGHT_TYPE: ATT\nNODE_COORD_SECTION\n1 0 0\n2 0 32\nEOF\n");
  // r = sqrt(102.4) = 10.119, nint = 10 < r -> 11
  EXPECT_EQ(tsplib_distance(u, 0, 1), 11.0);
}

TEST(Tsplib, GeoDistance) {
  // Two nodes one degree of latitude apart on the same meridian: about 111 km.
  const TsplibInstance t = parse("NAME: g\nTYPE: TSP\nDIMENSION: 2\nEDGE_WEIGHT_TYPE: GEO\nNODE_COORD_SECTION\n1 10.00 20.00\n2 11.00 20.00\nEOF\n");
  EXPECT_NEAR(tsplib_distance(t, 0, 1), 112.0, 1.0);
}

TEST(Tsplib, DepotSection) {
  const TsplibInstance t = parse(
      "NAME: d\nTYPE: TSP\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: EUC_2D\nNODE_COORD_SECTION\n1 0 0\n2 1 1\n3 2 2\n"
      "DEPOT_SECTION\n2\n-1\nEOF\n");
  ASSERT_EQ(t.depots.size(), 1u);
  EXPECT_EQ(t.depots[0], 1);
}

TEST(Tsplib, ErrorsNameTheLine) {
  EXPECT_EQ(error_of("NAME: x\nTYPE: TSP\nDIMENSION: 2\nEDGE_WEIGHT_TYPE: EUC_2D\nNODE_COORD_SECTION\n1 0 0\n2 zero 1\nEOF\n"),
            "test.tsp:7: expected '<node id> <x> <y>', got '2 zero 1'");
  EXPECT_EQ(error_of("NAME: x\nDIMENSION: two\n"), "test.tsp:2: DIMENSION 'two' is not an integer");
  // A header alone may not make the reader allocate for 98 million nodes (fuzz_tsplib: 46 s).
  EXPECT_EQ(error_of("NAME: x\nDIMENSION : 98027629\nEDGE_WEIGHT_TYPE : EUC_2D\nNODE_COORD_SECTION\n2 0 0\n"),
            "test.tsp:2: DIMENSION 98027629 above this reader's limit of 1000000");
  EXPECT_EQ(error_of("NAME: x\nDIMENSION: 2\nEDGE_WEIGHT_TYPE: MAN_3D\n"),
            "test.tsp:3: EDGE_WEIGHT_TYPE 'MAN_3D' is not supported (EUC_2D, CEIL_2D, ATT, GEO)");
  EXPECT_EQ(error_of("NAME: x\nDIMENSION: 2\nEDGE_WEIGHT_TYPE: EUC_2D\nNODE_COORD_SECTION\n1 0 0\n1 2 2\n"),
            "test.tsp:6: node id 1 appears twice");
  EXPECT_EQ(error_of("NAME: x\nDIMENSION: 3\nEDGE_WEIGHT_TYPE: EUC_2D\nNODE_COORD_SECTION\n1 0 0\n2 2 2\nEOF\n"),
            "test.tsp:7: NODE_COORD_SECTION ended after 2 of 3 nodes");
  EXPECT_EQ(error_of("NAME: x\nDIMENSION: 2\nEDGE_WEIGHT_TYPE: EUC_2D\nNODE_COORD_SECTION\n1 0 0\n5 2 2\n"),
            "test.tsp:6: node id 5 outside 1..2");
  EXPECT_EQ(error_of("NAME: x\nFOO BAR\n"), "test.tsp:2: expected 'KEY : value' or a section name, got 'FOO BAR'");
  EXPECT_EQ(error_of("NAME: x\nDIMENSION: 2\nNODE_COORD_SECTION\n"), "test.tsp:3: NODE_COORD_SECTION before EDGE_WEIGHT_TYPE");
}

TEST(Tsplib, MtspFromInstanceRemovesDepots) {
  const TsplibInstance t = parse(kSquare);
  const TsplibMtsp m = make_tsplib_mtsp(t, {0, 0}, {}, {}, 1, RouteKind::kClosed, true);
  EXPECT_EQ(m.problem.num_cities, 3);
  EXPECT_EQ(m.city_node, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(m.problem.travel_cost(0, m.problem.depot(1), 0), 5.0);
  EXPECT_THROW(make_tsplib_mtsp(t, {7}, {}, {}, 1, RouteKind::kClosed, true), std::invalid_argument);
}

}  // namespace
}  // namespace hexplore::planning
