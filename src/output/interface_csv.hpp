// rupture/output/interface_csv.hpp
// Interface profiles (theory §4, the paper's Fig. 12): DIR/interface/interface_NNNNNN.csv, one
// row per cohesive node: time (s), x (m), jump_n, jump_t (m), traction_n, traction_t (Pa,
// resisting magnitudes T^ at the node's jump, 0 once cracked), force_x, force_y (N/m, nodal
// cohesive force on the upper face; the lower face carries the opposite), y_upper, y_lower
// (deformed face positions, m), cracked (0/1). Written atomically.
#pragma once
#include <string>

#include "cohesive/interface.hpp"

namespace rupture {

// The traction at node k (Pa, normal and tangential in the node's frame), as the interface's
// law reports it (its LawEntry::node_traction, input/law_registry.hpp): a cohesive law at
// the node's jump (0 once cracked); friction the total traction T0 + dT of the Gauss points
// around it.
CohesiveTraction node_traction(const CohesiveInterface& c, std::size_t k);

void write_interface_csv(const std::string& path, const CohesiveInterface& c, double time);

}  // namespace rupture
