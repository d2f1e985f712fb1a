// Helpers for the wave verification tests: 1D strips (uniaxial strain via rollers) and
// front-arrival detection from particle stresses.
#pragma once
#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <string>

#include "input/case_toml.hpp"
#include "support.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"

namespace rupture::test {

// A Homalite strip [0, length] x [0, height] in plane strain. The left edge is driven with
// velocity `v` in component `drive` ("x" for a P wave, "y" for an S wave); top and bottom carry
// rollers on the other component so the motion is one-dimensional (no lateral waves).
inline Case strip_1d(double length, double height, double h, const std::string& drive, double v,
                     double end, const std::string& scheme = "MUSL") {
  const std::string roller = drive == "x" ? "y" : "x";
  const std::string text = fmt::format(R"({8}
[grid]
min = [0.0, 0.0]
max = [{0}, {1}]
cell_size = {2}
[bodies.strip]
material = "homalite"
min = [0.0, 0.0]
max = [{0}, {1}]
[time]
end = {5}
cfl = 0.4
[solver]
scheme = "{6}"
[boundary.drive]
edge = "left"
component = "{3}"
velocity = {4}
[boundary.bottom]
edge = "bottom"
component = "{7}"
velocity = 0.0
[boundary.top]
edge = "top"
component = "{7}"
velocity = 0.0
)",
                                       length, height, h, drive, v, end, scheme, roller, test::kHomaliteToml);
  return parse_case(text);
}

// Mean of `stress` over the particles whose x lies within [x0, x1].
inline double mean_over(const Particles& p, const std::vector<double>& stress, double x0, double x1) {
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.x[i] >= x0 && p.x[i] <= x1) sum += stress[i], ++n;
  return n ? sum / n : 0.0;
}

// Time at which the mean stress at station x first reaches half of `plateau` (linear
// interpolation between steps): the centre of the arriving front.
inline double arrival_time(State& s, double end, double x, double band,
                           const std::vector<double> Particles::*stress, double plateau) {
  double prev_t = s.time, prev_v = mean_over(s.particles, s.particles.*stress, x - band, x + band);
  while (s.time < end) {
    step(s);
    const double v = mean_over(s.particles, s.particles.*stress, x - band, x + band);
    if (std::fabs(v) >= 0.5 * std::fabs(plateau)) {
      const double target = 0.5 * plateau;
      return prev_t + (target - prev_v) / (v - prev_v) * (s.time - prev_t);
    }
    prev_t = s.time;
    prev_v = v;
  }
  return NAN;
}

}  // namespace rupture::test
