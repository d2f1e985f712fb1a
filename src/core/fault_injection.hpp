// rupture/core/fault_injection.hpp
// Failures on demand, for the tests of failure paths that no small input reaches on purpose
// (one rank's cohesive oscillation, a face past the halo, a write that fails on rank 0 ...).
// The environment variable RUPTURE_INJECT_FAULT = "SITE:RANK:STEP" arms one site on one process
// (its rank under mpirun, 0 alone) from the given step on; the code at that site then behaves
// as if it had found the failure itself, so the test exercises the real diagnosis and the
// real agreement. Unset (every real run) each site costs one predictable branch.
#pragma once
#include <string>

namespace rupture {

enum class FaultSite {
  none,
  face_outside_grid,     // solver/cohesive_step: update_face_stencils
  face_out_of_reach,     // parallel/halo_interface: check_faces_in_reach
  cohesive_oscillation,  // solver/cohesive_step: advance_interfaces
  gimp_contract,         // solver/particle_sort: check_gimp_contract
  record_write,          // run/run_io: rank 0's record files (history, crack tip, run.json)
  setup,                 // run/run_setup: this rank's set-up
  snapshot_index,        // output/snapshot: rank 0's particles.xdmf after a distributed snapshot
  case_read,             // cli/main: reading the case file (or the checkpoint's input), as if missing
};

// Reads RUPTURE_INJECT_FAULT for the process of rank `rank`; InputError on a malformed value.
void arm_fault_from_environment(int rank);

// Whether the armed site is `site` and `step` has reached the armed step (on this process).
bool fault_due(FaultSite site, long step);

}  // namespace rupture
