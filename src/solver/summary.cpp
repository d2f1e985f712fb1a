// rupture/solver/summary.cpp
#include "solver/summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cohesive/interface.hpp"
#include "grid/grid.hpp"
#include "grid/nested.hpp"
#include "particles/particles.hpp"
#include "particles/seed.hpp"
#include "solver/field_windows.hpp"
#include "solver/time_step.hpp"

namespace rupture {

namespace {

// Each field holds the nodes of its bodies' box plus stencil and margin (solver/field_windows).
long field_nodes_estimate(const Case& c, const Grid& grid) {
  std::vector<Box> field_box(c.field_names.size(), Box{{INFINITY, INFINITY}, {-INFINITY, -INFINITY}});
  for (const BodySpec& b : c.bodies) {
    const Box box = bounding_box(b.region);
    Box& f = field_box[std::size_t(b.field)];
    for (int d = 0; d < 2; ++d)
      f.min[d] = std::min(f.min[d], box.min[d]), f.max[d] = std::max(f.max[d], box.max[d]);
  }
  long nodes = 0;
  for (const Box& box : field_box)
    if (box.min[0] <= box.max[0]) nodes += long(window_nodes_estimate(grid, box));
  return nodes;
}

// The interfaces, counted from cohesive/interface.hpp's arrays: per node 20 doubles, the law,
// streak and rank-flag bytes and two face stencils; per segment 9 doubles; per Gauss point 6
// doubles and 3 bytes; the crack tracker's copy of the nodes (3 doubles) and the text of the
// rupture-time file written at the end (about 64 bytes a node).
std::size_t interface_bytes_estimate(const Case& c) {
  std::size_t bytes = 0;
  constexpr std::size_t kPerNode = 20 * sizeof(double) + 2 + 4 + 2 + 2 * sizeof(FaceStencil) + 3 * sizeof(double) + 64;
  constexpr std::size_t kPerSegment = 9 * sizeof(double) + CohesiveInterface::kGauss * (6 * sizeof(double) + 3);
  for (const InterfaceSpec& is : c.interfaces)
    bytes += std::size_t(is.segments) * kPerSegment + std::size_t(is.segments + 1) * kPerNode;
  return bytes;
}

// Whether some material is damped: its particles then carry the Kelvin-Voigt stress too.
bool damped(const Case& c) {
  return std::any_of(c.materials.begin(), c.materials.end(),
                     [](const ElasticMaterial& m) { return m.kelvin_voigt > 0.0; });
}

// The nodal arrays per field node (grid/grid.hpp, 11) + particle arrays + sort scratch (order,
// one double array for the permutation) + the interfaces.
double memory_bytes(long field_nodes, double particles, std::size_t interface_bytes, bool damped) {
  return double(interface_bytes) + double(field_nodes) * double(field_array_count() * sizeof(double)) +
         particles * double(Particles::bytes_per_particle(damped) + 12);
}

// grid.refinement = "nested": cells, particles and nodes of the levels (grid/nested.hpp), every
// field over every level's whole lattice (solver/nested_state.hpp).
void summarize_nested(const Case& c, CaseSummary& s) {
  const NestedGrid g = make_nested_grid(c.grid.min, c.grid.max, c.grid.coarse_cell_size,
                                        c.grid.cell_size, refine_boxes(c.grid), std::max(0.0, c.grid.margin));
  const int ppc = c.grid.particles_per_cell;
  s.nodes = long(g.num_nodes());
  std::fill(s.cells_per_level.begin(), s.cells_per_level.end(), 0);
  std::fill(s.particles_per_level.begin(), s.particles_per_level.end(), 0);
  const auto cells = count_level_cells(g, c.grid.min, c.grid.max, 1);
  s.cells = 0;
  for (std::size_t l = 0; l < cells.size() && l < s.cells_per_level.size(); ++l)
    s.cells_per_level[l] = long(cells[l].cells), s.cells += long(cells[l].cells);
  s.particles = 0;
  s.particles_per_body.clear();
  for (const BodySpec& b : c.bodies) {
    long n = 0;
    for (int l = 0; l < int(g.levels.size()); ++l)
      for_each_seed_point(level_grid(g, l), b.region, ppc, [&](const SeedPoint& p) {
        if (g.level_of(p.x, p.y) != l) return;
        ++n;
        if (std::size_t(l) < s.particles_per_level.size()) ++s.particles_per_level[std::size_t(l)];
      });
    s.particles_per_body.push_back(n);
    s.particles += n;
  }
  s.field_nodes = long(g.num_nodes()) * s.fields;
  s.memory_bytes = std::size_t(s.field_nodes) * field_array_count() * sizeof(double) +
                   std::size_t(s.particles) * (Particles::bytes_per_particle(damped(c)) + 12);
}

}  // namespace

CaseSummary summarize(const Case& c) {
  CaseSummary s;
  double max_cd = 0.0;
  for (const ElasticMaterial& m : c.materials) {
    s.speeds.push_back(wave_speeds(m, c.plane));
    max_cd = std::max(max_cd, s.speeds.back().dilatational);
  }
  // The grid is cheap to build (two axes); its smallest cell sets the CFL step.
  const Grid grid = build_grid(c.grid);
  const double h = std::min(grid.x.min_width(), grid.y.min_width());
  s.min_cell_size = h;
  // The averaged mass M_A = (M_L + M_C) / 2 >= M_L / 2 (M_C is positive semi-definite): the
  // largest eigenvalue of M_A^-1 K is at most twice the lumped one's, the step 1/sqrt(2) of it
  // (docs/theory.md §19).
  const double mass_factor = c.solver.mass == MassMatrix::averaged ? std::sqrt(0.5) : 1.0;
  s.dt_cfl = mass_factor * c.time.cfl * h / max_cd;
  s.dt = s.dt_cfl;
  // theory E6 as derived in solver/time_step.hpp. Bulk: the Gershgorin bound of uGIMP for each
  // material at the smallest cell. Cohesive, at rest: every face node sits on its row, so its
  // stencil holds the row's nodes of mass m = rho h^2 / 2 (per field) and the row sum is
  // (2 / m) k h with k the law's stiffness at rest, penalty included (a node carries a length
  // h of interface). The run recomputes both terms every step from the actual state.
  const int ppc = c.grid.particles_per_cell;
  // Kelvin-Voigt damping eta = f dt lowers the central-difference limit from omega dt <= 2 to
  // omega dt <= 2 / sqrt(1 + 2 f) (docs/theory.md §16): the bound's eigenvalue times (1 + 2 f).
  for (const ElasticMaterial& m : c.materials)
    s.bulk_eigen_bound =
        std::max(s.bulk_eigen_bound, (1.0 + 2.0 * m.kelvin_voigt) *
                                         bulk_eigen_bound(stiffness(m, c.plane), m.density, ppc, h));
  if (c.solver.mass == MassMatrix::averaged) s.bulk_eigen_bound *= 2.0;
  s.dt_bulk = 2.0 / std::sqrt(s.bulk_eigen_bound);
  for (const InterfaceSpec& is : c.interfaces) {
    const double rho = std::min(c.materials[c.bodies[is.upper_body].material].density,
                                c.materials[c.bodies[is.lower_body].material].density);
    double law_k = is.precracked ? 0.0 : stiffness_at_rest(is.law);
    for (const LawStretch& st : is.stretches)
      law_k = std::max(law_k, is.precracked ? 0.0 : stiffness_at_rest(st.law));
    const double contact_k = is.contact ? is.contact_law.stability_stiffness() : 0.0;
    const double k = std::max(law_k, contact_k) * h;
    const double m = 0.5 * rho * h * h;
    const double scheme = c.solver.scheme == Scheme::MUSL ? 1.0 : 2.0;  // solver/time_step.cpp
    const double limit = 2.0 / std::sqrt(scheme * (s.bulk_eigen_bound + 2.0 * k / m));
    s.dt_cohesive = s.dt_cohesive > 0 ? std::min(s.dt_cohesive, limit) : limit;
  }
  if (s.dt_cohesive > 0) s.dt = std::min(s.dt, c.time.cohesive_safety * s.dt_cohesive);
  // A double first: an absurd case (dt = 0, time.end = 1e308) must not overflow the count.
  s.steps_exact = s.dt > 0 ? std::ceil(c.time.end / s.dt - 1e-9) : INFINITY;
  s.steps = s.steps_exact < 9e18 ? long(s.steps_exact) : std::numeric_limits<long>::max();
  const long ppcl = ppc;
  const int levels =
      c.grid.refined() ? int(std::lround(std::log2(c.grid.coarse_cell_size / c.grid.cell_size))) + 1
                       : 1;
  s.cells_per_level.assign(std::size_t(levels), 0);
  s.particles_per_level.assign(std::size_t(levels), 0);
  for (int L = 0; L < levels; ++L)
    s.level_sizes.push_back(c.grid.refined() ? c.grid.level_size(L) : c.grid.cell_size);
  auto level_of = [&](double hx, double hy) {
    if (!c.grid.refined()) return 0;
    const int L = int(std::lround(std::log2(c.grid.coarse_cell_size / std::min(hx, hy))));
    return std::clamp(L, 0, levels - 1);
  };
  s.nodes = long(grid.num_nodes());
  s.ghost_cells = grid.ghost;
  if (!c.grid.refined()) {
    const long cx = std::lround((c.grid.max[0] - c.grid.min[0]) / h);
    const long cy = std::lround((c.grid.max[1] - c.grid.min[1]) / h);
    s.cells = cx * cy;
    s.cells_per_level[0] = s.cells;
    for (const BodySpec& b : c.bodies) {
      const long n = b.plain_rectangle() ? std::lround((b.max[0] - b.min[0]) / h) *
                                               std::lround((b.max[1] - b.min[1]) / h) * ppcl * ppcl
                                         : count_seed_points(grid, b.region, ppc);
      s.particles_per_body.push_back(n);
      s.particles += n;
    }
    s.particles_per_level[0] = s.particles;
  } else {
    // Physical cells, and particles of each body (ppc x ppc per cell it covers).
    const double tol = 1e-9 * grid.x.h;
    s.cells = 0;
    for (int j = grid.ghost; j < grid.y.cells - grid.ghost; ++j)
      for (int i = grid.ghost; i < grid.x.cells - grid.ghost; ++i) {
        ++s.cells;
        ++s.cells_per_level[std::size_t(level_of(grid.x.width(i), grid.y.width(j)))];
      }
    for (const BodySpec& b : c.bodies) {
      long n = 0;
      if (!b.plain_rectangle()) {
        for_each_seed_point(grid, b.region, ppc, [&](const SeedPoint& p) {
          ++n;
          ++s.particles_per_level[std::size_t(level_of(p.lx * ppc, p.ly * ppc))];
        });
        s.particles_per_body.push_back(n);
        s.particles += n;
        continue;
      }
      for (int j = 0; j < grid.y.cells; ++j) {
        const double yc = grid.y.node(j) + 0.5 * grid.y.width(j);
        if (yc < b.min[1] - tol || yc > b.max[1] + tol) continue;
        for (int i = 0; i < grid.x.cells; ++i) {
          const double xc = grid.x.node(i) + 0.5 * grid.x.width(i);
          if (xc < b.min[0] - tol || xc > b.max[0] + tol) continue;
          n += ppcl * ppcl;
          s.particles_per_level[std::size_t(level_of(grid.x.width(i), grid.y.width(j)))] +=
              ppcl * ppcl;
        }
      }
      s.particles_per_body.push_back(n);
      s.particles += n;
    }
  }
  s.fields = int(c.field_names.size());
  s.field_nodes = field_nodes_estimate(c, grid);
  const std::size_t interface_bytes = interface_bytes_estimate(c);
  if (c.grid.nested) {
    summarize_nested(c, s);
    s.memory_bytes += interface_bytes;
    return s;
  }
  s.memory_bytes = std::size_t(memory_bytes(s.field_nodes, double(s.particles), interface_bytes, damped(c)));
  return s;
}

double memory_bytes_before_seeding(const Case& c) {
  if (c.grid.refined()) return 0.0;
  const Grid grid = build_grid(c.grid);
  const double h = c.grid.cell_size, ppc = c.grid.particles_per_cell;
  // Each drawn body once, whatever the lines inside it split it into: its parts' points are
  // its own (the two sides of a cut share none and lose none, geometry/shape.hpp).
  double particles = 0.0;
  std::vector<const Region*> drawn;
  for (const BodySpec& b : c.bodies) {
    if (std::any_of(drawn.begin(), drawn.end(), [&](const Region* r) { return same_drawn_region(*r, b.region); }))
      continue;
    drawn.push_back(&b.region);
    const Region whole{b.region.outer, b.region.minus};
    const Shape& o = whole.outer;
    // A rectangle on grid lines: its cells times ppc^2, exactly (seed_rectangle's count).
    const auto on_line = [&](double v, int d) {
      const double n = (v - c.grid.min[d]) / h;
      return std::fabs(n - std::round(n)) <= 1e-9 * std::max(1.0, std::fabs(n));
    };
    const bool exact = o.kind == ShapeKind::rectangle && whole.minus.empty() && on_line(o.min[0], 0) &&
                       on_line(o.max[0], 0) && on_line(o.min[1], 1) && on_line(o.max[1], 1);
    particles += exact ? std::round((o.max[0] - o.min[0]) / h) * std::round((o.max[1] - o.min[1]) / h) * ppc * ppc
                       : seed_points_at_least(whole, h / ppc);
  }
  return memory_bytes(field_nodes_estimate(c, grid), particles, interface_bytes_estimate(c), damped(c));
}

}  // namespace rupture
