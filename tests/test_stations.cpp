// Body stations read = "interpolated" (output/stations.hpp): the linear least-squares fit of
// the particles within a cell reproduces a linear field at the point exactly, inside a body and
// on its free surface (extrapolated), where the nearest particle reads it a quarter of a cell
// off; points on one line give no fit; a fault station refuses the key.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "output/stations.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

// The 2 x 2 particle lattice of cells h below y = 0 (a free surface), x in [0, 10h].
std::vector<NearestParticle::Point> surface_lattice(double h) {
  std::vector<NearestParticle::Point> pts;
  std::uint32_t id = 0;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 20; ++i) pts.push_back({(i + 0.5) * h / 2, -(j + 0.5) * h / 2, id++});
  return pts;
}

double linear(double x, double y) { return 3.0 - 2.0 * x + 5.0 * y; }

}  // namespace

TEST(Stations, fit_reproduces_a_linear_field_inside_and_on_the_free_surface) {
  const double h = 10.0;
  const std::vector<NearestParticle::Point> lattice = surface_lattice(h);
  for (const auto& [x0, y0] : std::vector<std::pair<double, double>>{{50.0, 0.0}, {43.0, 0.0}, {50.0, -17.0}}) {
    NearestParticle n{x0, y0, h};
    for (const auto& p : lattice) n.visit(p.x, p.y, p.id);
    ASSERT_GE(n.near.size(), 3u);
    const std::vector<double> w = linear_fit_weights(n.near, x0, y0);
    ASSERT_EQ(w.size(), n.near.size());
    double value = 0.0, sum = 0.0;
    for (std::size_t k = 0; k < w.size(); ++k) value += w[k] * linear(n.near[k].x, n.near[k].y), sum += w[k];
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_NEAR(value, linear(x0, y0), 1e-11) << "at (" << x0 << ", " << y0 << ")";
    // The nearest particle reads the field where it is, not at the point.
    EXPECT_GT(std::fabs(linear(n.best_x, n.best_y) - linear(x0, y0)), 1.0);
  }
}

TEST(Stations, points_on_one_line_or_too_few_give_no_fit) {
  std::vector<NearestParticle::Point> line;
  for (std::uint32_t k = 0; k < 5; ++k) line.push_back({double(k), 2.0 * double(k), k});
  EXPECT_TRUE(linear_fit_weights(line, 0.5, 1.0).empty());
  EXPECT_TRUE(linear_fit_weights({{0.0, 0.0, 0}, {1.0, 0.0, 1}}, 0.5, 0.0).empty());
  EXPECT_EQ(linear_fit_weights({{0.0, 0.0, 0}, {1.0, 0.0, 1}, {0.0, 1.0, 2}}, 0.2, 0.3).size(), 3u);
}

TEST(Stations, interpolated_read_is_for_body_stations) {
  const std::string fault = test::case_with(test::kGeometry + "sigma_max = 10e6\ndelta_n = 1e-5\n") +
                            "[stations.s]\nat = [0.004, 0.0]\ninterface = \"w\"\nread = \"interpolated\"\n";
  try {
    parse_case(fault);
    ADD_FAILURE() << "a fault station with read = \"interpolated\" was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("stations.s.read"), std::string::npos) << e.what();
  }
  const Case c = parse_case(test::case_with(test::kGeometry + "sigma_max = 10e6\ndelta_n = 1e-5\n") +
                            "[stations.b]\nat = [0.004, 0.002]\nread = \"interpolated\"\n");
  ASSERT_EQ(c.stations.size(), 1u);
  EXPECT_TRUE(c.stations[0].interpolated);
}
