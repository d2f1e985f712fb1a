// Rotation invariance of interfaces (cohesive/interface.hpp: a frame per segment) and loads:
// the reference problem (cropped, uniform 0.5 mm) turned by +90 degrees, (x, y) -> (-y, x),
// is the same discrete problem (the grid, the particles and the tensor-product GIMP weights map
// onto themselves), so its crack must be the same to round-off: the weak plane now runs up the
// line x = 0 (tangent +y, normal -x), the bonded stretch is a vertical tie, and the impact
// drives the bottom edge in +y. The rotation by 30 degrees (staircase boundaries, a tie band
// across grid lines) is a study: docs/validation.md.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "input/case_toml.hpp"
#include "run/driver.hpp"

using namespace rupture;

namespace {
RunResult run_quietly(const Case& c, const std::string& name) {
  RunOptions o;
  o.output_dir = (std::filesystem::temp_directory_path() / ("rupture_rotation_" + name)).string();
  o.progress = false;
  o.overwrite = true;
  return run_case(c, o);
}
}  // namespace

TEST(Rotation, reference_problem_turned_by_90_degrees_cracks_identically) {
  const std::string src = RUPTURE_SOURCE_DIR;
  const Case plain = load_case(src + "/examples/rosakis1999.toml",
                               {"grid.coarse_cell_size=0", "grid.min=[0.0,-0.06]", "grid.max=[0.075,0.04]",
                                "bodies.upper.max=[0.075,0.04]", "bodies.lower.min=[0.0,-0.06]",
                                "bodies.lower.max=[0.075,0.0]", "interface.weak_plane.bonded_to=0.075",
                                "time.end=12e-6", "output.snapshot_interval=0", "output.interface_interval=0"});
  const Case turned = load_case(src + "/tests/data/reference_turned_90.toml");
  const RunResult a = run_quietly(plain, "plain"), b = run_quietly(turned, "turned");
  ASSERT_TRUE(a.ok) << a.message;
  ASSERT_TRUE(b.ok) << b.message;
  ASSERT_EQ(a.cracks.size(), 1u);
  ASSERT_EQ(b.cracks.size(), 1u);
  const CrackSummary &p = a.cracks[0], &t = b.cracks[0];
  std::printf("initiation %.12g / %.12g s, peak speed %.9g / %.9g m/s, tip s %.9g / %.9g m, energy error %.6g / %.6g\n",
              p.initiation_time, t.initiation_time, p.peak_speed, t.peak_speed, p.final_tip_s, t.final_tip_s,
              a.energy_balance_error, b.energy_balance_error);
  ASSERT_TRUE(p.initiated) << "the reference problem initiates at ~10.6 us";
  // Round-off only: a summation order differs (particles are sorted by columns).
  EXPECT_NEAR(t.initiation_time, p.initiation_time, 1e-6 * p.initiation_time);
  EXPECT_NEAR(t.peak_speed, p.peak_speed, 1e-6 * p.peak_speed);
  EXPECT_NEAR(t.final_tip_s, p.final_tip_s, 1e-9);
  // The tip moves along the line: in the turned problem it runs up x = 0.
  EXPECT_NEAR(t.final_tip, 0.0, 1e-12);
  EXPECT_NEAR(t.final_tip_y, p.final_tip, 1e-9);
  EXPECT_NEAR(b.energy_balance_error, a.energy_balance_error, 1e-6);
}
