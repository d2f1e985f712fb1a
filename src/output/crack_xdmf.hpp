// rupture/output/crack_xdmf.hpp
// The paths of the cracks that grow, for ParaView: DIR/cracks.xdmf, beside DIR/particles.xdmf,
// one XDMF 3 temporal collection per growing crack (Grid "crack_NAME") at the snapshots' times,
// each step a Polyline of the crack as it was at that time: the drawn line with the vertices it
// had grown by then added at its ends (solver/crack_growth.hpp, crack_path_NAME.csv), in
// reference coordinates (m, z = 0), and each branch split off a tip by then (from the split
// point along its vertices) in the same Polyline's cells, the numbers inline (no HDF5 file of its own). Opened beside
// particles.xdmf, ParaView shows the crack lines over the particles at every output time.
// Derived from what the checkpoint holds (the grown segments and the snapshot times), so a
// resumed run rewrites the same file.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "input/case.hpp"
#include "solver/crack_growth.hpp"

namespace rupture {

// Interface k's path at time t (s): its vertices in order along the line, m.
std::vector<std::array<double, 2>> crack_path_at(const Case& c, std::size_t k, const CrackGrowthRecord& growth,
                                                 double t);
// The branches split off by time t (s), in tip-label order: the split point, then the
// branch's vertices, m.
std::vector<std::vector<std::array<double, 2>>> crack_branches_at(const CrackGrowthRecord& growth, double t);
// The file's text; empty when no crack grows or there are no times.
std::string cracks_xdmf(const Case& c, const std::vector<CrackGrowthRecord>& growth,
                        const std::vector<double>& times);
// Writes DIR/cracks.xdmf (atomically) when cracks_xdmf is not empty.
void write_cracks_xdmf(const std::string& dir, const Case& c, const std::vector<CrackGrowthRecord>& growth,
                       const std::vector<double>& times);

}  // namespace rupture
