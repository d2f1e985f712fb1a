// Tests of output/crack_xdmf.hpp: a growing crack's path at time t is the drawn line with the
// vertices grown by t at its ends (the start's in reverse order of growth, so the path runs
// along the line), and cracks.xdmf holds one Polyline per snapshot time with that many points
// and segments; no growing crack or no snapshot writes nothing.
#include <gtest/gtest.h>

#include <string>

#include "output/crack_xdmf.hpp"

namespace rupture {
namespace {

// One crack drawn from (0, 0) to (1, 0) (through (0.5, 0)) that grew at its end at t = 1 and 2
// and at its start at t = 1.5 and 3.
struct Grown {
  Case c;
  std::vector<CrackGrowthRecord> growth{1};
  Grown() {
    InterfaceSpec is;
    is.line.x = {0.0, 0.5, 1.0};
    is.line.y = {0.0, 0.0, 0.0};
    is.growth.criterion = GrowthCriterion::max_hoop;
    c.interfaces.push_back(is);
    c.interface_names.push_back("crack");
    auto row = [&](double t, int end, double x, double y) {
      growth[0].rows.push_back({t, end, end == 0 ? LineEnd::start : LineEnd::end, false, x, y, 0.0, 0.1, 0.0, 0.0});
    };
    row(1.0, 1, 1.1, 0.0), row(1.5, 0, -0.1, 0.05), row(2.0, 1, 1.2, 0.05), row(3.0, 0, -0.2, 0.1);
  }
};

TEST(CrackXdmf, ThePathAtATimeIsTheDrawnLineWithWhatHadGrownAtItsEnds) {
  const Grown g;
  using P = std::vector<std::array<double, 2>>;
  EXPECT_EQ(crack_path_at(g.c, 0, g.growth[0], 0.5), (P{{0.0, 0.0}, {0.5, 0.0}, {1.0, 0.0}}));
  EXPECT_EQ(crack_path_at(g.c, 0, g.growth[0], 1.7),
            (P{{-0.1, 0.05}, {0.0, 0.0}, {0.5, 0.0}, {1.0, 0.0}, {1.1, 0.0}}));
  EXPECT_EQ(crack_path_at(g.c, 0, g.growth[0], 10.0),
            (P{{-0.2, 0.1}, {-0.1, 0.05}, {0.0, 0.0}, {0.5, 0.0}, {1.0, 0.0}, {1.1, 0.0}, {1.2, 0.05}}));
}

TEST(CrackXdmf, OnePolylinePerSnapshotTime) {
  const Grown g;
  const std::string x = cracks_xdmf(g.c, g.growth, {0.5, 2.0});
  EXPECT_NE(x.find("<Grid Name=\"crack_crack\" GridType=\"Collection\" CollectionType=\"Temporal\">"), std::string::npos);
  // t = 0.5: 3 points, 2 segments; t = 2: 6 points (one at the start, two at the end), 5 segments.
  EXPECT_NE(x.find("NumberOfElements=\"2\" NodesPerElement=\"2\""), std::string::npos);
  EXPECT_NE(x.find("Dimensions=\"3 3\""), std::string::npos);
  EXPECT_NE(x.find("NumberOfElements=\"5\" NodesPerElement=\"2\""), std::string::npos);
  EXPECT_NE(x.find("Dimensions=\"6 3\""), std::string::npos);
  EXPECT_NE(x.find(" 0 1 1 2 2 3 3 4 4 5<"), std::string::npos);
  EXPECT_NE(x.find("<Time Value=\"2.000000000e+00\"/>"), std::string::npos);
  EXPECT_EQ(x.find("step2"), std::string::npos);
  // Nothing to write: no snapshot, or no crack that grows.
  EXPECT_EQ(cracks_xdmf(g.c, g.growth, {}), "");
  Grown still;
  still.c.interfaces[0].growth.criterion = GrowthCriterion::none;
  EXPECT_EQ(cracks_xdmf(still.c, still.growth, {1.0}), "");
}

}  // namespace
}  // namespace rupture
