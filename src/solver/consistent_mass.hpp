// rupture/solver/consistent_mass.hpp
// solver.mass = "averaged" (docs/theory.md §19): the grid equations with the consistent mass
// M_C,ij = sum_p m_p S_ip S_jp (a 5 x 5 band per node: a particle's stencil spans three nodes
// per axis) instead of the lumped M_L,i = sum_j M_C,ij alone. FLIP MPM with the lumped mass
// moves the grid velocity with M_L^-1 M_C M_L^-1 (the re-map smooths it once more), whose
// dispersion is three times the lumped finite element's; with the grid velocity projected with
// M_C (v = M_C^-1 p) and the acceleration taken with the averaged mass M_A = (M_L + M_C) / 2
// (Krieg & Key 1973, Marfurt 1984) it is M_A^-1: the (kh)^2 term of the phase error cancels.
// Both solves are a fixed number of Richardson sweeps preconditioned with M_L, each result
// written back as lumped-mass momentum or force (M_L x), so the updates that follow (velocity
// BCs, absorbing edges, regions) divide by m_i as before. Per field; one level (input/
// case_checks refuses the rest). Distributed: each rank's band holds its own particles, and
// every sweep's product sums over the ranks at their shared nodes (halo_sum_lanes).
#pragma once

#include "solver/state.hpp"

namespace rupture {

// Richardson sweeps of each solve. A sweep multiplies the error by 1 - lambda, lambda an
// eigenvalue of M_L^-1 M (M_C or M_A), 1 - lambda = O((kh)^2) for a resolved wave: two sweeps
// put the phase speed within 0.08 % of the exact solve's at kh = 0.8 (8 cells per wavelength),
// one sweep 0.8 % (docs/theory.md §19, the 2 x 2 particle lattice's Bloch analysis).
inline constexpr int kMassSweeps = 2;

// The band of every field from the particles' stencils (the step's windows and positions).
void assemble_consistent_mass(State& s);

// (bx, by) <- M_L M^-1 (bx, by) by kMassSweeps sweeps from M_L^-1 b: M = M_C for a momentum
// (to the velocity at the step's start or, MUSL's re-map, its end), M = M_A for a force (to
// the acceleration). Node components a [boundary] condition drives are known, not solved:
// the prescribed velocity (at that time) or its change over the step over dt. Nodes at or
// below the mass floor hold 0. Needs assemble_consistent_mass of this step.
enum class MassSolve { momentum_at_start, momentum_at_end, force };
void solve_mass(State& s, MassSolve kind, double* bx, double* by);

// The step's two solves in one pass over the band: the momentum with M_C, the force with M_A.
void solve_momentum_and_force(State& s);

// y = M_C x, one component over every field's window (the tests' and the solve's product).
void apply_consistent_mass(const State& s, const double* x, double* y);

}  // namespace rupture
