// Kelvin-Voigt damping (material/elastic.hpp: kelvin_voigt; docs/theory.md §16) against the
// damped plane wave: sigma = C : (eps + eta eps_dot) makes a plane P wave of angular frequency
// omega decay with distance as exp(-alpha x), alpha = Im k for k = (omega / c) / sqrt(1 + i omega
// eta) (about omega^2 eta / (2 c) for omega eta << 1). A Ricker pulse pushed into a rollered
// strip is recorded at two distances; the ratio of the two records' spectra, damped over
// undamped (which takes out the grid's own dispersion and the source), is exp(-alpha dx).
// Also: the energy balance holds with the viscous work as dissipation, and the time-step bound
// shrinks by sqrt(1 + 2 eta/dt).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "solver/energy.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "solver/summary.hpp"

using namespace rupture;

namespace {

constexpr double kH = 0.5e-3, kLength = 0.1, kWidth = 1e-3;  // m
constexpr double kX1 = 0.02, kX2 = 0.06;                      // the two records, m
constexpr double kF0 = 3.0e5, kT0 = 5e-6, kEnd = 3.8e-5;      // Ricker, Hz and s; run, s

std::string strip(double kelvin_voigt) {
  return fmt::format(R"(
[materials.homalite]
youngs_modulus = 5.2e9
poisson_ratio = 0.34
density = 1246.0
kelvin_voigt = {0}
[grid]
min = [0.0, 0.0]
max = [{1}, {2}]
cell_size = {3}
[bodies.strip]
material = "homalite"
min = [0.0, 0.0]
max = [{1}, {2}]
[time]
end = {4}
cfl = 0.4
[boundary.a]
edge = "bottom"
component = "y"
velocity = 0.0
[boundary.b]
edge = "top"
component = "y"
velocity = 0.0
[loads.push]
type = "traction"
from = [0.0, 0.0]
to = [0.0, {2}]
traction = [1e5, 0.0]
function = "ricker"
frequency = {5}
delay = {6}
)",
                     kelvin_voigt, kLength, kWidth, kH, kEnd, kF0, kT0);
}

double mean_vx_near(const Particles& P, double x) {
  double v = 0.0;
  int n = 0;
  for (std::size_t p = 0; p < P.size(); ++p)
    if (std::fabs(P.x[p] - x) < 0.5 * kH) v += P.vx[p], ++n;
  return v / n;
}

struct Record {
  double dt = 0.0;
  std::vector<double> v1, v2;  // particle velocity at kX1, kX2, every step, m/s
  double energy_error = 0.0, viscous_work = 0.0, kinetic_plus_strain = 0.0;
};

Record run(double kelvin_voigt) {
  State s = make_state(parse_case(strip(kelvin_voigt)));
  Record r;
  while (s.time < kEnd - 1e-6 * s.dt) {
    s.dt_cap = kEnd - s.time;
    step(s);
    if (r.v1.empty()) r.dt = s.dt;  // the run's step (the last one is cut to end at kEnd)
    r.v1.push_back(mean_vx_near(s.particles, kX1));
    r.v2.push_back(mean_vx_near(s.particles, kX2));
  }
  const double ke = kinetic_energy(s.particles), se = strain_energy(s.particles, s.stiffness);
  r.kinetic_plus_strain = ke + se;
  r.viscous_work = s.viscous_work;
  r.energy_error = std::fabs(s.initial_energy + s.external_work - ke - se - s.viscous_work) /
                   std::fabs(s.external_work);
  return r;
}

// The DFT of a record at angular frequency w (the step dt).
std::complex<double> spectrum(const std::vector<double>& v, double dt, double w) {
  std::complex<double> sum = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k)
    sum += v[k] * std::exp(std::complex<double>(0.0, -w * dt * double(k)));
  return sum;
}
double amplitude(const std::vector<double>& v, double dt, double w) { return std::abs(spectrum(v, dt, w)); }

// The group delay from x1 to x2 of a run's records, -d(phase of V2/V1)/dw, s.
double group_delay(const Record& r, double w) {
  const double dw = 1e-3 * w;
  auto phase = [&](double x) { return std::arg(spectrum(r.v2, r.dt, x) / spectrum(r.v1, r.dt, x)); };
  return -std::remainder(phase(w + dw) - phase(w - dw), 2.0 * std::numbers::pi) / (2.0 * dw);
}

}  // namespace

TEST(KelvinVoigt, plane_wave_decays_as_the_damped_wave_equation_predicts) {
  const double f = 0.1;  // eta = 0.1 dt, as SEM2DPACK and PyLith
  const Record damped = run(f), undamped = run(0.0);
  ASSERT_EQ(damped.v1.size(), undamped.v1.size());
  const double dt = damped.dt, eta = f * dt;
  const double E = 5.2e9, nu = 0.34, rho = 1246.0;
  const double c = std::sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho));
  const double dx = kX2 - kX1;
  // Over the band where the pulse carries energy (its spectrum above half the peak at x1).
  const double w0 = 2.0 * std::numbers::pi * kF0;
  double peak = 0.0;
  for (double w = 0.2 * w0; w <= 2.5 * w0; w += 0.05 * w0) peak = std::max(peak, amplitude(undamped.v1, dt, w));
  int checked = 0;
  double worst_continuum = 0.0, worst_discrete = 0.0;
  for (double w = 0.2 * w0; w <= 2.5 * w0; w += 0.05 * w0) {
    if (amplitude(undamped.v1, dt, w) < 0.5 * peak) continue;
    const double ratio = (amplitude(damped.v2, dt, w) / amplitude(damped.v1, dt, w)) /
                         (amplitude(undamped.v2, dt, w) / amplitude(undamped.v1, dt, w));
    const double measured = -std::log(ratio);
    // The continuum: alpha dx, alpha = Im k.
    const std::complex<double> k = (w / c) / std::sqrt(std::complex<double>(1.0, w * eta));
    const double continuum = std::fabs(k.imag()) * dx;
    // The grid's own wave: a mode of frequency w decays in time at eta w^2 / 2 (the damping is
    // eta times the stiffness, whose eigenvalue for that mode is w^2) and its energy travels at
    // the group speed, so over dx the exponent is (eta w^2 / 2) x the group delay, which the
    // undamped records give. This takes out the grid's dispersion, which slows short waves.
    const double discrete = 0.5 * eta * w * w * group_delay(undamped, w);
    // The measurement's own floor at w: how far the undamped run's |V2 / V1| is from 1 (a ripple
    // of +-0.018 over the band: the strip's lateral modes), which the ratio does not fully cancel.
    const double floor = std::fabs(std::log(amplitude(undamped.v2, dt, w) / amplitude(undamped.v1, dt, w)));
    worst_discrete = std::max(worst_discrete, (std::fabs(measured - discrete) - floor) / discrete);
    if (w <= w0)  // at least 17 cells per wavelength: the continuum's exponent too
      worst_continuum = std::max(worst_continuum, (std::fabs(measured - continuum) - floor) / continuum);
    const double undamped_exponent = -std::log(amplitude(undamped.v2, dt, w) / amplitude(undamped.v1, dt, w));
    (void)undamped_exponent;
    std::printf("omega/omega0 = %.2f (%.1f cells per wavelength): decay over %.0f mm %.4f; exponent %.4f, "
                "continuum %.4f, with the grid's group delay %.4f; undamped run's own %.4f\n",
                w / w0, 2 * std::numbers::pi * c / w / kH, 1e3 * dx, ratio, measured, continuum, discrete,
                undamped_exponent);
    ++checked;
  }
  EXPECT_GT(checked, 10);
  // Beyond the floor: within 5 % of the grid wave's exponent over the whole band (10 to 34 cells
  // per wavelength), within 10 % of the continuum's where the grid resolves the wave.
  EXPECT_LT(worst_discrete, 0.05) << "largest relative error of the decay exponent, beyond the floor";
  EXPECT_LT(worst_continuum, 0.10) << "against the continuum (17 cells per wavelength and more)";
  RecordProperty("worst_exponent_error_discrete", fmt::format("{:.4f}", worst_discrete));
  RecordProperty("worst_exponent_error_continuum", fmt::format("{:.4f}", worst_continuum));
  std::printf("decay exponent: largest error %.2f %% against the grid's wave, %.2f %% against the continuum\n",
              100 * worst_discrete, 100 * worst_continuum);
  // Energy: the balance closes with the viscous work, which is positive and is what the damped
  // run's bodies hold less than the undamped's (the same load; it works against slower motion
  // only to second order).
  // (The undamped balance, 2.1 %, is the traction pulse's own: its work through the edge nodes.
  // Without the viscous work the damped one would be off by 60 %.)
  EXPECT_LT(damped.energy_error, undamped.energy_error + 0.005);
  EXPECT_LT(undamped.energy_error, 0.03);
  EXPECT_GT(damped.viscous_work, 0.0);
  EXPECT_EQ(undamped.viscous_work, 0.0);
  std::printf("energy error: damped %.3e, undamped %.3e; viscous work %.4e J/m, kinetic + strain "
              "%.4e (damped) vs %.4e J/m (undamped)\n",
              damped.energy_error, undamped.energy_error, damped.viscous_work,
              damped.kinetic_plus_strain, undamped.kinetic_plus_strain);
}

// omega dt <= 2 / sqrt(1 + 2 f) for the explicit central-difference form with eta = f dt: the
// bulk eigenvalue bound grows by (1 + 2 f).
TEST(KelvinVoigt, step_bound_shrinks_by_sqrt_of_one_plus_twice_eta_over_dt) {
  const CaseSummary a = summarize(parse_case(strip(0.0))), b = summarize(parse_case(strip(0.3)));
  EXPECT_NEAR(b.bulk_eigen_bound / a.bulk_eigen_bound, 1.6, 1e-12);
  EXPECT_NEAR(a.dt_bulk / b.dt_bulk, std::sqrt(1.6), 1e-12);
}

TEST(KelvinVoigt, out_of_range_value_is_named) {
  for (const char* bad : {"-0.1", "1.5"}) {
    std::string text = strip(0.0);
    text.replace(text.find("kelvin_voigt = 0"), 16, std::string("kelvin_voigt = ") + bad);
    try {
      parse_case(text);
      ADD_FAILURE() << "expected an InputError for " << bad;
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("materials.homalite.kelvin_voigt"), std::string::npos) << m;
      EXPECT_NE(m.find("[0, 1]"), std::string::npos) << m;
    }
  }
}
