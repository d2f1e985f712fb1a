// rupture/run/energy_check.hpp
// The energy history's samples (E14) and the check that stops a run going unstable. A sample
// holds the run's energies summed over the particles and, distributed, over the ranks (every
// rank takes part: collective), with the interfaces' stored and dissipated energy. The check
// throws SimulationError, naming the step, the fastest particle and time.cfl, once the bodies
// hold more than twice the energy supplied to them.
#pragma once
#include "output/history.hpp"
#include "solver/run_state.hpp"

namespace rupture {

// The run's energies at its current time (distributed: one sum over the ranks of each rank's
// particles, owned nodes and owned interface segments).
EnergySample sample_energy(RunState& s);

// Throws SimulationError when the kinetic + strain energy of sample e exceeds twice the energy
// supplied: the initial energy, the most the loads' work has been (`peak_work`, J/m, updated
// here) and the energy the interfaces released into the bulk.
void check_energy(RunState& s, const EnergySample& e, double& peak_work);

}  // namespace rupture
