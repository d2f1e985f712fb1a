// rupture/solver/summary.hpp
// Quantities derived from a Case without allocating it: wave speeds (theory E1), time step
// (theory E6), sizes and a memory estimate. Used by `rupture check` and written to run.json.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "input/case.hpp"
#include "material/elastic.hpp"

namespace rupture {

struct CaseSummary {
  std::vector<WaveSpeeds> speeds;  // per material
  double dt_cfl = 0.0;             // cfl * h / max c_D, s
  double dt_cohesive = 0.0;        // stability limit with the interfaces at rest, s (0 = none):
                                   // 2 / sqrt(lambda_bulk + lambda_cohesive), solver/time_step.hpp
  double bulk_eigen_bound = 0.0;   // lambda_bulk, 1/s^2
  double dt_bulk = 0.0;            // 2 / sqrt(lambda_bulk): the bulk's own bound, s
  double dt = 0.0;                 // step used, s
  long steps = 0;                  // ceil(end / dt) (LONG_MAX when that does not fit)
  double steps_exact = 0.0;        // ceil(end / dt) as a double (inf when dt = 0)
  long cells = 0;                  // physical cells
  long nodes = 0;                  // grid nodes, ghosts included
  long field_nodes = 0;            // nodes the fields' windows hold at t = 0, summed over fields
  int ghost_cells = 2;             // ghost cells on each side (grid.margin)
  std::vector<long> particles_per_body;
  long particles = 0;
  int fields = 0;
  // Refined grids (theory §5): cells and particles per level. A cell's level is that of its
  // smaller side, log2(coarse_cell_size / min(hx, hy)); uniform grids have one level.
  std::vector<long> cells_per_level, particles_per_level;
  std::vector<double> level_sizes;  // m
  double min_cell_size = 0.0;       // m
  std::size_t memory_bytes = 0;    // particles + per-field grid arrays + scatter plan
};

CaseSummary summarize(const Case& c);

// summarize's memory estimate without walking any body's seed points (input/ refuses an absurd
// case with it before the walks, which cost as much as the particles): the particles of each
// drawn body counted once over the parts its lines split it into, exactly for a rectangle on
// grid lines and at least (particles/seed.hpp, seed_points_at_least) for other shapes; the
// fields' windows and the interfaces as summarize counts them. So at most summarize's
// memory_bytes, equal for rectangles. Bytes; 0 on a refined grid (not estimated).
double memory_bytes_before_seeding(const Case& c);

}  // namespace rupture
