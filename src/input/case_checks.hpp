// rupture/input/case_checks.hpp
// Consistency checks across the tables of a parsed Case, run by input/case_toml before any work:
//  - two boundary conditions prescribing the same velocity component on shared nodes (same
//    edge, overlapping ranges, a body in common) with different time functions: InputError
//    naming both keys, their values and what is allowed (identical ones: a warning);
//  - bodies of different velocity fields that touch along a segment of nonzero length (two
//    rectangles: along x or y = const; other shapes: particle boxes sharing an edge) with no
//    [interface] between their fields: InputError (they would pass through each other; an
//    interface of law = "contact" asks for contact);
//  - a run of more than 1e7 time steps: a warning;
//  - a Ricker wavelet whose shortest S wavelength (at 2.5 f0) spans fewer than 8 cells: a warning.
// Warnings are appended to Case::warnings; the CLI prints them as `warning: ...` on stderr.
#pragma once
#include "input/case.hpp"

namespace rupture {

void check_case_consistency(Case& c);

// The grid alone, before anything walks the bodies' seed points (which cost as much as the grid
// holds): its node count within the 32-bit particle sort and its fields (one velocity field, 11
// doubles a node) within solver.memory_limit_mib, or the machine's memory; on a uniform grid,
// the particles too, counted without a walk (the plain rectangles exactly, other shapes at least:
// particles/seed.hpp, seed_points_at_least), within the 32-bit ids and, with the grid, the
// memory. An absurd case is refused here, at once, not after minutes of counting particles it
// could never hold.
void check_grid_limits(const Case& c);

// Once every line has split its body (input/parse_interfaces), before any check walks seed
// points: the whole case's memory estimate as `rupture check` gives it (solver/summary.hpp,
// memory_bytes_before_seeding: exact for rectangles, at least for other shapes), within
// solver.memory_limit_mib or the machine's memory. A body split into parts by its cracks is
// refused here, not after minutes of walks over every part.
void check_memory_before_seeding(const Case& c);

}  // namespace rupture
