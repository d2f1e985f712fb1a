// rupture/particles/seed.hpp
// Where a body's particles go (theory §2, §5). Every grid cell is cut into ppc x ppc sub-cells of
// its own size; a particle sits at the centre of each sub-cell whose centre lies in the body's
// region, with the sub-cell's area as its volume and half its sides as GIMP half-widths. The
// boundary is thus a staircase of sub-cells, exact for rectangles on grid lines and first-order
// accurate in h otherwise (docs/geometry.md). Particles are appended row by row from the
// bottom, left to right within a row, at rest and stress-free, with `id` = their index.
// Units: m, kg/m^3, m/s.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>

#include "geometry/shape.hpp"
#include "grid/grid.hpp"
#include "particles/particles.hpp"

namespace rupture {

// One sub-cell: its centre and sides, m.
struct SeedPoint {
  double x, y;    // centre
  double lx, ly;  // sides (the particle's volume is lx * ly, its half-widths lx/2, ly/2)
};

// What every particle of one body gets besides its position and size.
struct SeedProperties {
  double density = 0.0;  // kg/m^3
  std::uint8_t field = 0, material = 0;
  double velocity[2]{};  // m/s
};

using SeedVisit = std::function<void(const SeedPoint&)>;

// Visits, in seeding order, the sub-cell centres inside `r` on grid `g` (uniform or graded).
// The sub-cells are those of the grid cells the region's bounding box overlaps; on a uniform
// grid their centres are counted from the box's lower-left corner when it lies on grid lines
// (so a rectangle given as a polygon gets bitwise the positions seed_rectangle gives it), from
// the grid line below it otherwise.
void for_each_seed_point(const Grid& g, const Region& r, int ppc,
                         const SeedVisit& visit);
// The same points, but only those inside `within` (a box; the walk covers no more than it and
// the region's box, geometry/shape.hpp region_box): a check that looks at part of a body
// visits only that part.
void for_each_seed_point(const Grid& g, const Region& r, int ppc, const Box& within, const SeedVisit& visit);

// How many particles region `r` gets.
long count_seed_points(const Grid& g, const Region& r, int ppc);

// At least how many sub-cell centres of a uniform lattice of spacing `s` (m) lie in `r`, from
// areas and perimeters alone (no walk: input/ refuses an absurd case with it at once). A sub-cell
// lies wholly inside the outer shape S where its centre is more than its diameter sqrt(2) s from
// S's boundary, and the r-neighbourhood of a closed curve of length P covers at most
// 2 r P + pi r^2; a cut-out C holds at most (A_C + sqrt(2) s P_C + pi s^2 / 2) / s^2 centres
// (their disjoint sub-cells lie within s / sqrt(2) of C). So the count is at least
// [A_S - 2 sqrt(2) s P_S - 2 pi s^2 - sum_C (A_C + sqrt(2) s P_C + pi s^2 / 2)] / s^2, and 0
// where that is negative. A region cut by lines (r.sides) gets 0.
double seed_points_at_least(const Region& r, double s);

// Appends the particles of region `r`; returns how many.
std::size_t seed_region(Particles& p, const Grid& g, const Region& r, int ppc,
                        const SeedProperties& props);

// A rectangle whose edges lie on lines of a graded grid (theory §5): every cell whose centre lies
// in [min, max] gets ppc x ppc particles of the cell's own size. Appends to `p`.
void seed_graded_rectangle(Particles& p, const Grid& g, const double min[2], const double max[2],
                           int ppc, const SeedProperties& props);

// Visits, in their order, the particles seed_graded_rectangle appends.
void for_each_graded_rectangle_point(const Grid& g, const double min[2], const double max[2], int ppc,
                                     const SeedVisit& visit);

// Visits, in their order and bitwise at their positions, the particles seed_rectangle
// (particles/particles.hpp) appends.
void for_each_rectangle_point(const double min[2], const double max[2], double h, int ppc,
                              const double origin[2], const SeedVisit& visit);

// Appends one particle at `s` with identity `id` (a distributed run's rank keeps some of a
// case's particles, numbered as one process numbers them).
void append_seed_point(Particles& p, const SeedPoint& s, const SeedProperties& props, std::uint32_t id);

}  // namespace rupture
