// rupture/solver/time_step.hpp
// The explicit step's stability bound (theory E6), derived from the discrete system that is
// integrated rather than from a lumped two-node model (derivation: docs/time_step.md).
// Central differences are stable while dt <= 2 / sqrt(lambda_max) of M^-1 K. With the bulk
// and the cohesive stiffness added, lambda_max <= lambda_bulk + lambda_cohesive (Weyl), and
// each term is bounded by the largest Gershgorin row sum of its own M^-1 K:
//   lambda_bulk      = max over materials of the row-sum bound of a regularly seeded uGIMP
//                      block (interior, edge and corner nodes) / h_min^2 (once per run);
//   lambda_cohesive  = max over grid nodes i of (2 / m_i) sum_k k_k c_ki: the face stencils c
//                      actually used, the nodal masses m_i of this step, and k_k the face
//                      node's tributary tangent stiffness (the law's largest eigenvalue,
//                      penalty included) at the current openings (every step).
//   dt = min(cfl h_min / c_D, cohesive_safety * 2 / sqrt(lambda_bulk + lambda_cohesive)).
// Units: 1/s^2 for eigenvalues, s for steps.
#pragma once
#include "material/elastic.hpp"
#include "solver/state.hpp"

namespace rupture {

// Largest Gershgorin row sum of M^-1 K for uGIMP with ppc x ppc particles per cell of size h,
// material stiffness C and density rho, over the nodes of a free square block (interior,
// edges and corners), 1/s^2.
double bulk_eigen_bound(const ElasticStiffness& C, double density, int ppc, double h);

// Gershgorin bound of the cohesive part at this step (needs the face stencils of this step:
// solver/cohesive_step.hpp, update_face_stencils), 1/s^2; 0 without interfaces.
double cohesive_eigen_bound(const State& s);

// Sets s.dt for this step from the bounds above, the CFL step and s.dt_cap (the time left to
// the end of the run); s.forced_dt > 0 overrides the bound (tests only).
void choose_time_step(State& s);

}  // namespace rupture
