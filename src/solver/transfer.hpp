// rupture/solver/transfer.hpp
// Particle <-> grid transfers of the time step (theory E3-E5), each a free function over the
// State's plain arrays, per velocity field: the scatters use the race-free strip plan
// (ScatterPlan, kept up to date by build_scatter_plan), the gathers plain parallel loops.
// grid_to_particles throws SimulationError (what, where, when) on a non-finite particle or one
// leaving the grid; a re-sort checks the GIMP contract on graded grids.
#pragma once
#include <cstddef>
#include <vector>

#include "solver/state.hpp"

namespace rupture {

void build_scatter_plan(State& s);  // re-sort the particles when due (solver/particle_sort.cpp)
void sort_particles(State& s);
void particles_to_grid(State& s, bool with_force);  // mass, momentum [, internal force] (E4)
void particles_to_grid_force(State& s);             // internal force only (USF)
void update_particle_velocity_and_remap(State& s);  // FLIP/PIC blend + MUSL re-map (scatter)
// The same two scatters over several States at once (nested levels: one parallel region, the
// threads' work spread over every level's strips). Same results as one call per State.
void particles_to_grid(State* const* states, std::size_t count, bool with_force);
void update_particle_velocity_and_remap(State* const* states, std::size_t count);
// Stress update with the grid velocity (s.fields.*gx, s.fields.*gy) (E5); optionally update
// velocity (USL) and move particles with the t^{n+1} grid velocity. Each State with its own dt.
using NodalArray = std::vector<double> GridFields::*;
enum class G2PMode { stress_and_move, stress_velocity_and_move, stress_only, velocity_and_move };
void grid_to_particles(State& s, NodalArray gx, NodalArray gy, G2PMode mode);
// The same over several States in one parallel region (nested levels); same results as one
// call per State.
void grid_to_particles(State* const* states, std::size_t count, NodalArray gx, NodalArray gy,
                       G2PMode mode);

}  // namespace rupture
