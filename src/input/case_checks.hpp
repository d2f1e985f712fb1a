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

}  // namespace rupture
