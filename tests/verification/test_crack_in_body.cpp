// Cracks inside one body (interface.NAME.body, docs/interfaces.md), checked on the physics:
//  1. The same problem written two ways gives the same answer: the reference problem cropped
//     (x <= 75 mm, -60 <= y <= 40 mm, uniform 1 mm, to 12 us) with an edge weak plane from x = 0
//     to 50 mm, as two rectangles with bonded_to = 0.075 (examples/rosakis1999.toml) and as one
//     plate with body = "plate" (examples/edge_crack_in_plate.toml), where the stretch from 50 to
//     75 mm is tied automatically. The particles are the same but for the last bit of the lower
//     part's coordinates (its rows are counted from the plate's bottom, not the lower
//     rectangle's), so the runs agree to round-off, not necessarily bitwise.
//  2. A centre crack with both ends inside (tests/inputs/centre_crack_in_plate.toml), opened by
//     a pressure on the faces of its middle, is symmetric about its centre: the tip and the back
//     tip stay equally far from it, mirrored nodes crack at the same time and open the same.
//     Without the tie beyond one end the openings differ by 2e-3 of their size (measured with the
//     two-body form and one bonded_points stretch), far above the tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "input/case_toml.hpp"
#include "run/driver.hpp"

using namespace rupture;

namespace {

std::string run_dir(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("rupture_crack_in_body_" + name)).string();
}

RunResult run_quietly(const Case& c, const std::string& name) {
  RunOptions o;
  o.output_dir = run_dir(name);
  o.progress = false;
  o.overwrite = true;
  return run_case(c, o);
}

// A CSV file of numbers by column name (nan and inf allowed).
std::map<std::string, std::vector<double>> read_csv(const std::string& path) {
  std::map<std::string, std::vector<double>> out;
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot read " << path;
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream ss(line); std::getline(ss, cell, ',');) names.push_back(cell);
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    for (const std::string& n : names) {
      std::getline(ss, cell, ',');
      out[n].push_back(std::strtod(cell.c_str(), nullptr));
    }
  }
  return out;
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v)
    if (std::isfinite(x)) m = std::max(m, std::fabs(x));
  return m;
}

// Largest |a - b| over the finite entries (both nan counts as equal), and whether the lengths
// and the nan positions agree.
double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
    EXPECT_EQ(std::isnan(a[k]), std::isnan(b[k])) << "row " << k;
    if (std::isfinite(a[k]) && std::isfinite(b[k])) d = std::max(d, std::fabs(a[k] - b[k]));
  }
  return d;
}

}  // namespace

TEST(CrackInBody, edge_weak_plane_in_one_plate_equals_two_rectangles_with_bonded_to) {
  const std::string src = RUPTURE_SOURCE_DIR;
  const std::vector<std::string> common = {
      "grid.cell_size=1e-3",         "time.end=12e-6",   "output.snapshot_interval=0",
      "output.interface_interval=0", "solver.threads=1", "interface.weak_plane.segments=2000"};
  std::vector<std::string> two = {
      "grid.coarse_cell_size=0",        "grid.min=[0.0,-0.06]",
      "grid.max=[0.075,0.04]",          "bodies.upper.max=[0.075,0.04]",
      "bodies.lower.min=[0.0,-0.06]",   "bodies.lower.max=[0.075,0.0]",
      "interface.weak_plane.start=0.0", "interface.weak_plane.bonded_to=0.075"};
  two.insert(two.end(), common.begin(), common.end());
  const Case rectangles = load_case(src + "/examples/rosakis1999.toml", two);
  const Case plate = load_case(src + "/examples/edge_crack_in_plate.toml", common);
  ASSERT_EQ(plate.bodies.size(), 2u);
  ASSERT_EQ(plate.interfaces[0].tie_geometries().size(), 1u);
  const RunResult a = run_quietly(rectangles, "rectangles"), b = run_quietly(plate, "plate");
  ASSERT_TRUE(a.ok) << a.message;
  ASSERT_TRUE(b.ok) << b.message;
  const CrackSummary &p = a.cracks[0], &q = b.cracks[0];
  ASSERT_TRUE(p.initiated);
  EXPECT_GT(p.final_tip, 0.02) << "the crack runs, so the comparison means something";
  std::printf(
      "initiation %.12g / %.12g s, tip %.9g / %.9g m, peak speed %.9g / %.9g m/s, "
      "energy error %.9g / %.9g\n",
      p.initiation_time, q.initiation_time, p.final_tip, q.final_tip, p.peak_speed, q.peak_speed,
      a.energy_balance_error, b.energy_balance_error);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_NEAR(q.initiation_time, p.initiation_time, 1e-9 * p.initiation_time);
  EXPECT_NEAR(q.final_tip, p.final_tip, 1e-12);
  EXPECT_NEAR(q.sustained_speed, p.sustained_speed, 1e-9 * std::fabs(p.sustained_speed));
  EXPECT_NEAR(b.energy_balance_error, a.energy_balance_error, 1e-9);
  // The whole tip history (every 0.02 us) and every energy of the history.
  const auto ta = read_csv(run_dir("rectangles") + "/crack_tip.csv");
  const auto tb = read_csv(run_dir("plate") + "/crack_tip.csv");
  for (const char* col : {"time", "tip_s", "back_s", "cohesive_zone_length", "speed"}) {
    const double d = max_difference(ta.at(col), tb.at(col));
    std::printf("crack_tip.csv %-22s max difference %.3g (of %.3g)\n", col, d, max_abs(ta.at(col)));
    EXPECT_LE(d, 1e-9 * max_abs(ta.at(col))) << col;
  }
  const auto ha = read_csv(run_dir("rectangles") + "/history.csv");
  const auto hb = read_csv(run_dir("plate") + "/history.csv");
  const double scale = max_abs(ha.at("external_work"));
  for (const char* col : {"kinetic_energy", "strain_energy", "external_work", "cohesive_stored",
                          "cohesive_dissipated", "balance"}) {
    const double d = max_difference(ha.at(col), hb.at(col));
    std::printf("history.csv   %-22s max difference %.3g J/m (external work %.4g J/m)\n", col, d,
                scale);
    EXPECT_LE(d, 1e-9 * scale) << col;
  }
}

TEST(CrackInBody, centre_crack_with_both_ends_inside_runs_symmetrically) {
  const std::string src = RUPTURE_SOURCE_DIR;
  const Case c = load_case(src + "/tests/inputs/centre_crack_in_plate.toml",
                           {"solver.threads=1", "output.interface_interval=2e-6"});
  ASSERT_EQ(c.interfaces[0].tie_geometries().size(), 2u) << "tied beyond both ends";
  const RunResult r = run_quietly(c, "centre");
  ASSERT_TRUE(r.ok) << r.message;
  const double centre = 0.015, segment = 0.03 / 600;  // arc length of x = 0; segment length, m
  const auto tip = read_csv(run_dir("centre") + "/crack_tip_centre.csv");
  double worst = 0.0, reach = 0.0;
  for (std::size_t k = 0; k < tip.at("tip_s").size(); ++k) {
    if (tip.at("stretches")[k] == 0) continue;
    const double ahead = tip.at("tip_s")[k] - centre, behind = centre - tip.at("back_s")[k];
    worst = std::max(worst, std::fabs(ahead - behind));
    reach = std::max(reach, ahead);
  }
  std::printf(
      "tips %.4g mm from the centre at the end; largest |tip - back| difference %.3g m "
      "(segment %.3g m)\n",
      1e3 * reach, worst, segment);
  EXPECT_GT(reach, 0.005) << "the crack runs beyond the 3 mm loaded stretch";
  EXPECT_LT(reach, 0.015) << "and stays inside the weak plane";
  EXPECT_LE(worst, segment);
  // Mirrored nodes crack at the same time (node k and node N - k).
  const auto times = read_csv(run_dir("centre") + "/rupture_time_centre.csv");
  const std::vector<double>& t = times.at("crack_time");
  double time_gap = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double u = t[t.size() - 1 - k];
    EXPECT_EQ(t[k] < 0.0, u < 0.0) << "node " << k << " and its mirror";
    if (t[k] >= 0.0 && u >= 0.0) time_gap = std::max(time_gap, std::fabs(t[k] - u));
  }
  std::printf("mirrored crack times differ by at most %.3g s\n", time_gap);
  EXPECT_LE(time_gap, 1e-12);
  // Mirrored nodes open the same (normal jump even, tangential odd), the tied ends not at all.
  for (const auto& entry : std::filesystem::directory_iterator(run_dir("centre") + "/interface")) {
    const auto p = read_csv(entry.path().string());
    const std::vector<double>&jn = p.at("jump_n"), &jt = p.at("jump_t");
    const double size = max_abs(jn);
    double odd = 0.0, even = 0.0;
    for (std::size_t k = 0; k < jn.size(); ++k) {
      odd = std::max(odd, std::fabs(jn[k] - jn[jn.size() - 1 - k]));
      even = std::max(even, std::fabs(jt[k] + jt[jt.size() - 1 - k]));
    }
    std::printf(
        "t = %.3g s: largest opening %.3g m, mirror differences %.3g (normal), %.3g "
        "(tangential) m, end openings %.3g, %.3g m\n",
        p.at("time")[0], size, odd, even, jn.front(), jn.back());
    EXPECT_LE(odd, 1e-6 * size + 1e-15);
    EXPECT_LE(even, 1e-6 * size + 1e-15);
    EXPECT_LE(std::fabs(jn.front()), 1e-6 * size + 1e-15) << "tied beyond the start";
    EXPECT_LE(std::fabs(jn.back()), 1e-6 * size + 1e-15) << "tied beyond the end";
  }
}
