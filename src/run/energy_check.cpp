// rupture/run/energy_check.cpp
#include "run/energy_check.hpp"

#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>
#include <fmt/format.h>

#include "core/errors.hpp"
#include "parallel/halo.hpp"
#include "solver/energy.hpp"

namespace rupture {

EnergySample sample_energy(RunState& s) {
  // Distributed: the sums over particles, owned nodes and owned segments, added over the ranks
  // in one reduction (no interface state gathered: a history sampled at every step costs one
  // small sum, not every interface array).
  const std::size_t n = s.num_interfaces();
  std::vector<double> sums(4 + 2 * n);
  sums[0] = kinetic_energy(all_particles(s));
  sums[1] = s.strain_work, sums[2] = s.external_work, sums[3] = s.viscous_work;
  for (std::size_t k = 0; k < n; ++k) {
    sums[4 + 2 * k] = s.interface(k).stored_energy();
    sums[5 + 2 * k] = s.interface(k).work;
  }
  if (s.halo) halo_of(s).comm.sum(sums.data(), int(sums.size()));
  EnergySample e{s.time, sums[0], sums[1], sums[2], s.initial_energy};
  e.viscous_dissipated = sums[3];
  for (std::size_t k = 0; k < n; ++k) {
    const double stored = sums[4 + 2 * k];
    e.cohesive_stored += stored;
    e.cohesive_dissipated += sums[5 + 2 * k] - stored;  // work not stored in it (E14)
  }
  return e;
}

// An explicit scheme that goes unstable grows its energy without bound; twice the energy put
// in is far outside any discretization error and catches it long before overflow. The energy
// put in by the loads is the most their work has been so far (`peak_work`, J/m, updated
// here): absorbing edges take it out again (negative work), and what is left in the bodies
// (a reflection's worth) must not read as a blow-up.
void check_energy(RunState& s, const EnergySample& e, double& peak_work) {
  // A prestressed fault (traction-offset form) releases energy into the bulk: its work on the
  // bodies, -work > 0, is supplied too.
  double released = 0.0;
  for (std::size_t k = 0; k < s.num_interfaces(); ++k) released += std::max(0.0, -interface_work(s, k));
  peak_work = std::max(peak_work, std::fabs(e.external_work));
  const double supplied = e.initial + peak_work + released;
  const double mechanical = e.kinetic + e.strain;
  if (mechanical <= 2.0 * supplied || mechanical <= 0.0) return;
  // A prestressed fault creeping at its initial rate (rate-and-state: 1e-16 m/s in TPV103)
  // moves the bulk at that rate: energies of 1e-22 J/m, where the trapezoidal work and the
  // particles' energy differ by round-off alone. Below 1e-12 of the faults' own energy scale
  // (their prestress held by their stick springs, |T0|^2 / k L, J/m) nothing is resolved.
  double fault_scale = 0.0;
  for (std::size_t k = 0; k < s.num_interfaces(); ++k) {
    const CohesiveInterface& c = s.interface(k);
    std::visit(
        [&](const auto& l) {
          if constexpr (requires { l.tt0; l.tn0; })
            fault_scale += (l.tt0 * l.tt0 + l.tn0 * l.tn0) / l.initial_stiffness() * c.length();
        },
        c.spec.law);
  }
  if (mechanical <= 1e-12 * fault_scale) return;
  const Particles& P = all_particles(s);
  std::size_t fastest = 0;
  double vmax = -1.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const double v = std::hypot(P.vx[p], P.vy[p]);
    if (v > vmax) vmax = v, fastest = p;
  }
  throw SimulationError(fmt::format(
      "unstable: energy blow-up at step {}, t = {:.6g} s: kinetic + strain = {:.6g} J/m exceeds "
      "twice the energy supplied ({:.6g} J/m); fastest particle {} at (x, y) = ({:.6g}, {:.6g}) "
      "m with |v| = {:.6g} m/s; reduce time.cfl",
      s.step, s.time, mechanical, supplied, fastest, P.x[fastest], P.y[fastest], vmax));
}

}  // namespace rupture
