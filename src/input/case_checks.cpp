// rupture/input/case_checks.cpp
#include "input/case_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include "bc/absorbing.hpp"  // edge_name
#include "core/errors.hpp"
#include "input/toml_section.hpp"
#include "particles/seed.hpp"
#include "solver/nested_state.hpp"  // the one upward include (docs/architecture.md, The layers)
#include "solver/summary.hpp"

namespace rupture {
namespace {


// The time function as the input states it, e.g. "velocity = 10 (trapezoid: rise_time = 1e-07,
// plateau_time = 1.5e-05, fall_time = 1e-06)".
std::string describe(const VelocityBC& bc) {
  const TimeFunction& f = bc.velocity;
  if (f.kind == TimeFunction::Kind::constant)
    return fmt::format("velocity = {:g} (constant)", f.value);
  if (f.kind == TimeFunction::Kind::smooth_ramp)
    return fmt::format("velocity = {:g} (smooth_ramp: rise_time = {:g})", f.value, f.rise_time);
  if (f.kind == TimeFunction::Kind::ricker)
    return fmt::format("velocity = {:g} (ricker: frequency = {:g}, delay = {:g})", f.value,
                       f.frequency, f.delay);
  if (f.kind == TimeFunction::Kind::table)
    return fmt::format("velocity from a table of {} points ({:g} m/s at t = {:g} s ... {:g} m/s at "
                       "t = {:g} s)",
                       f.table_t.size(), f.table_v.front(), f.table_t.front(), f.table_v.back(),
                       f.table_t.back());
  return fmt::format(
      "velocity = {:g} (trapezoid: rise_time = {:g}, plateau_time = {:g}, fall_time = {:g})",
      f.value, f.rise_time, f.plateau_time, f.fall_time);
}

bool same_function(const TimeFunction& a, const TimeFunction& b) {
  if (a.kind == TimeFunction::Kind::table || b.kind == TimeFunction::Kind::table)
    return a.kind == b.kind && a.value == b.value && a.table_t == b.table_t &&
           a.table_v == b.table_v;
  return a.kind == b.kind && a.value == b.value &&
         (a.kind == TimeFunction::Kind::constant ||
          (a.rise_time == b.rise_time && a.plateau_time == b.plateau_time &&
           a.fall_time == b.fall_time && a.frequency == b.frequency && a.delay == b.delay));
}

// Bodies (by name) both conditions act on; an empty field list means every body.
std::vector<std::string> shared_bodies(const Case& c, const VelocityBC& a, const VelocityBC& b) {
  std::vector<std::string> names;
  for (const BodySpec& body : c.bodies) {
    auto acts = [&](const VelocityBC& bc) {
      return bc.fields.empty() || std::count(bc.fields.begin(), bc.fields.end(), body.field) > 0;
    };
    if (acts(a) && acts(b)) names.push_back(body.name);
  }
  return names;
}

// theory E2: a node takes one prescribed value per component. resolve_nodes() applies the
// conditions in input order, so of two that disagree the later one would silently win.
void check_boundary_conflicts(Case& c) {
  const Grid grid = build_grid(c.grid);
  for (std::size_t i = 0; i < c.boundary.size(); ++i)
    for (std::size_t j = i + 1; j < c.boundary.size(); ++j) {
      const VelocityBC &a = c.boundary[i], &b = c.boundary[j];
      if (a.edge != b.edge || a.component != b.component) continue;
      const bool vertical = a.edge == Edge::left || a.edge == Edge::right;
      const Axis& along = vertical ? grid.y : grid.x;
      const double lo = std::max(a.from, b.from), hi = std::min(a.to, b.to), tol = 1e-9 * along.h;
      if (hi < lo - tol) continue;
      if (hi - lo <= tol) {  // ranges meet at a point: shared only if a node lies there
        const int k = along.cell_of(lo);
        if (std::fabs(along.node(k) - lo) > tol && std::fabs(along.node(k + 1) - lo) > tol)
          continue;
      }
      const std::vector<std::string> bodies = shared_bodies(c, a, b);
      if (bodies.empty()) continue;
      std::string names;
      for (const std::string& n : bodies) names += (names.empty() ? "" : ", ") + n;
      const std::string where =
          fmt::format("v_{} on the {} edge for {} {}, {} in [{:g}, {:g}] m",
                      a.component == 0 ? "x" : "y", edge_name(a.edge),
                      bodies.size() > 1 ? "bodies" : "body", names, vertical ? "y" : "x", lo, hi);
      if (same_function(a.velocity, b.velocity)) {
        c.warnings.push_back(
            fmt::format("boundary.{} and boundary.{} both prescribe {} with the same {}: "
                        "redundant (one of them is enough)",
                        a.name, b.name, where, describe(a)));
        continue;
      }
      throw InputError(fmt::format(
          "input keys 'boundary.{}' and 'boundary.{}' both prescribe {}, with different values: "
          "boundary.{}: {}; boundary.{}: {}. A node takes one prescribed velocity per component: "
          "give both the same function and values, or make their from/to ranges, edges or bodies "
          "disjoint",
          a.name, b.name, where, a.name, describe(a), b.name, describe(b)));
    }
}

constexpr const char* kPassThrough =
    "they are two velocity fields, so they would pass through each other. Join them with an "
    "[interface.NAME] (upper_body, lower_body): a cohesive law, law = \"contact\" for faces "
    "that only press and rub (friction), bonded_points / bonded_to to tie a stretch; or give "
    "them the same bodies.NAME.field to make them one continuum";

// Two plain rectangles touch along a segment of a line x = const or y = const.
void check_touching_rectangles(const Case& c, const BodySpec& a, const BodySpec& b) {
  const double tol = 1e-9 * c.grid.cell_size;
  for (int d = 0; d < 2; ++d) {  // contact across a line of constant coordinate d
    const int e = 1 - d;
    const double lo = std::max(a.min[e], b.min[e]), hi = std::min(a.max[e], b.max[e]);
    if (hi - lo <= tol) continue;
    const bool a_below = std::fabs(a.max[d] - b.min[d]) <= tol;
    if (a_below || std::fabs(b.max[d] - a.min[d]) <= tol) {
      const double line = a_below ? a.max[d] : a.min[d];
      throw InputError(fmt::format(
          "bodies.{} and bodies.{} touch along {} = {:g} m, {} in [{:g}, {:g}] m, but no "
          "[interface] joins them: {}",
          a.name, b.name, d == 0 ? "x" : "y", line, e == 0 ? "x" : "y", lo, hi, kPassThrough));
    }
  }
}

// Any other shapes touch where a particle box of one shares a stretch of edge with (or
// overlaps) a particle box of the other. Boxes are bucketed by grid cell: a box touching
// another has its centre in the same or a neighbouring cell.
void check_touching_shapes(const Case& c, const Grid& grid, const BodySpec& a, const BodySpec& b) {
  const int ppc = c.grid.particles_per_cell;
  const double gap = c.grid.refined() ? c.grid.coarse_cell_size : c.grid.cell_size;
  // Only where the two regions' boxes come within a cell of each other (a part of a split body:
  // the box of the side that bounds it) are their points walked.
  const Box ba = region_box(a.region), bb = region_box(b.region);
  if (!boxes_overlap(ba, bb, gap)) return;
  Box close_by;
  for (int d = 0; d < 2; ++d)
    close_by.min[d] = std::max(ba.min[d], bb.min[d]) - gap, close_by.max[d] = std::min(ba.max[d], bb.max[d]) + gap;
  // b's points there, bucketed by grid cell: sorted by the cell's number (one array, not one
  // allocation a cell; stable, so each cell keeps the walk's order).
  struct InCell {
    std::int64_t cell;
    SeedPoint p;
  };
  const std::int64_t row = std::int64_t(grid.x.cells) + 2;  // cells -1 .. cells per row
  const auto cell = [&](int i, int j) { return std::int64_t(j) * row + std::int64_t(i + 1); };
  std::vector<InCell> cells;
  for_each_seed_point(grid, b.region, ppc, close_by, [&](const SeedPoint& p) {
    cells.push_back({cell(grid.x.cell_of(p.x), grid.y.cell_of(p.y)), p});
  });
  if (cells.empty()) return;
  std::stable_sort(cells.begin(), cells.end(), [](const InCell& u, const InCell& v) { return u.cell < v.cell; });
  const double tol = 1e-9 * grid.cell_size();
  std::vector<Point> contacts;
  for_each_seed_point(grid, a.region, ppc, close_by, [&](const SeedPoint& p) {
    const int ci = grid.x.cell_of(p.x), cj = grid.y.cell_of(p.y);
    for (int j = cj - 1; j <= cj + 1; ++j)
      for (int i = ci - 1; i <= ci + 1; ++i) {
        const std::int64_t k = cell(i, j);
        auto it = std::lower_bound(cells.begin(), cells.end(), k, [](const InCell& u, std::int64_t v) { return u.cell < v; });
        for (; it != cells.end() && it->cell == k; ++it) {
          const SeedPoint& q = it->p;
          const double gx = std::fabs(p.x - q.x) - 0.5 * (p.lx + q.lx);
          const double gy = std::fabs(p.y - q.y) - 0.5 * (p.ly + q.ly);
          // Sharing a stretch of edge: touching in one direction, overlapping in the other.
          if (std::max(gx, gy) <= tol && std::min(gx, gy) < -tol)
            contacts.push_back({0.5 * (p.x + q.x), 0.5 * (p.y + q.y)});
        }
      }
  });
  if (contacts.empty()) return;
  // Report the contact point nearest the mean of all of them.
  Point mean;
  for (const Point& q : contacts) mean.x += q.x / double(contacts.size()), mean.y += q.y / double(contacts.size());
  const Point near = *std::min_element(contacts.begin(), contacts.end(), [&](const Point& u, const Point& v) {
    return std::hypot(u.x - mean.x, u.y - mean.y) < std::hypot(v.x - mean.x, v.y - mean.y);
  });
  throw InputError(fmt::format(
      "bodies.{} and bodies.{} touch near ({:g}, {:g}) m ({} particle faces in contact), but no "
      "[interface] joins them: {}",
      a.name, b.name, near.x, near.y, contacts.size(), kPassThrough));
}

// Bodies of two velocity fields (theory §3) interact only through an interface between their
// fields. Touching without one, they would pass through each other: an input error (the user
// asks for contact with an interface of law = "contact"). Bodies of one field are one
// continuum: touching is what they are for.
void check_touching_bodies(const Case& c) {
  std::optional<Grid> grid;  // built only if a shape other than a plain rectangle needs it
  for (std::size_t i = 0; i < c.bodies.size(); ++i)
    for (std::size_t j = i + 1; j < c.bodies.size(); ++j) {
      const BodySpec &a = c.bodies[i], &b = c.bodies[j];
      if (a.field == b.field) continue;
      const bool joined =
          std::any_of(c.interfaces.begin(), c.interfaces.end(), [&](const InterfaceSpec& s) {
            // Every field a face lies on (a face changes field at a T-junction).
            auto on = [](const std::vector<FaceField>& faces, int whole, int field) {
              return faces.empty() ? whole == field
                                   : std::any_of(faces.begin(), faces.end(),
                                                 [&](const FaceField& f) { return f.field == field; });
            };
            return (on(s.upper_faces, s.upper_field, a.field) && on(s.lower_faces, s.lower_field, b.field)) ||
                   (on(s.upper_faces, s.upper_field, b.field) && on(s.lower_faces, s.lower_field, a.field));
          });
      if (joined) continue;
      if (a.plain_rectangle() && b.plain_rectangle()) {
        check_touching_rectangles(c, a, b);
        continue;
      }
      if (!grid) grid = build_grid(c.grid);
      check_touching_shapes(c, *grid, a, b);
    }
}

}  // namespace


namespace {

constexpr double kManySteps = 1e7;
// Above this many steps the schedules' tolerance, 1e-6 dt (run/run_setup.cpp), is below the
// round-off of the time itself (2^-52 time.end): outputs and the end time could be missed or
// repeated, and near the bound t + dt rounds back to t. 2^52 x 1e-6 = 4.5e9 steps.
constexpr double kMostSteps = 4503599627.370496;

void warn_long_run(Case& c, const CaseSummary& s) {
  if (s.steps_exact <= kManySteps) return;
  c.warnings.push_back(fmt::format(
      "the run takes {:.0f} time steps (more than 1e7): time.end = {:g} s at dt = {:.4g} s ({}); "
      "check time.end and grid.cell_size",
      s.steps_exact, c.time.end, s.dt,
      s.dt < s.dt_cfl ? "the cohesive stability limit x time.cohesive_safety, docs/theory.md E6"
                      : "time.cfl x the smallest cell / c_D, docs/theory.md E6"));
}

// A Ricker wavelet of peak frequency f0 carries energy up to about 2.5 f0 (its spectrum there is
// 3 % of the peak); the shortest S wavelength c_S / (2.5 f0) needs 8 cells (a common rule for
// low-order schemes; docs/loads.md) or the waves it sends disperse.
void warn_ricker_resolution(Case& c) {
  double cs = INFINITY;
  for (const ElasticMaterial& m : c.materials) cs = std::min(cs, wave_speeds(m, c.plane).shear);
  auto check = [&](const TimeFunction& f, const std::string& key) {
    if (f.kind != TimeFunction::Kind::ricker) return;
    const double wavelength = cs / (2.5 * f.frequency), cells = wavelength / c.grid.cell_size;
    if (cells >= 8.0) return;
    c.warnings.push_back(fmt::format(
        "'{}.frequency' = {:g} Hz: the shortest S wavelength it carries, c_S / (2.5 f0) = {:.4g} m "
        "(c_S = {:.6g} m/s), spans {:.3g} cells of grid.cell_size = {:g} m, fewer than 8: the "
        "waves will disperse; use a cell of at most {:.4g} m or a lower frequency",
        key, f.frequency, wavelength, cs, cells, c.grid.cell_size, wavelength / 8.0));
  };
  for (const PointForceLoad& l : c.loads.point_forces) check(l.factor, "loads." + l.name);
  for (const TractionLoad& l : c.loads.tractions) check(l.factor, "loads." + l.name);
  for (const BodyForceLoad& l : c.loads.body_forces) check(l.factor, "loads." + l.name);
  for (const VelocityBC& b : c.boundary) check(b.velocity, "boundary." + b.name);
}

// The machine's physical memory, bytes (0 when unknown).
double machine_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : 0.0;
}

// An estimate of `mib` MiB (`what` needs it; `detail` says of what) above solver.memory_limit_mib,
// or the machine's memory when that is 0: refused, naming the key.
void check_memory(const Case& c, double mib, const std::string& what, const std::string& detail) {
  const double machine = machine_memory_bytes() / (1024.0 * 1024.0);
  const double limit = c.solver.memory_limit_mib > 0 ? c.solver.memory_limit_mib : machine;
  if (limit > 0 && mib > limit)
    fail("solver.memory_limit_mib", limit,
         fmt::format("{} needs about {} MiB{} and this machine has {:.0f} MiB; use a coarser "
                     "grid.cell_size, nested levels, more ranks, or set solver.memory_limit_mib above "
                     "the estimate to run anyway",
                     what, mib >= 10.0 ? fmt::format("{:.0f}", mib) : fmt::format("{:.2g}", mib), detail,
                     machine));
}

// Finite but absurd inputs: what the run derives from them must be finite and in range
// before any allocation or step (wave speeds, the step, the step count, memory, 32-bit ids).
void check_run_limits(const Case& c, const CaseSummary& s) {
  for (std::size_t k = 0; k < c.materials.size(); ++k) {
    const ElasticMaterial& m = c.materials[k];
    const WaveSpeeds& w = s.speeds[k];
    if (std::isfinite(w.dilatational) && std::isfinite(w.shear) && w.dilatational > 0 && w.shear > 0)
      continue;
    fail("materials." + m.name, fmt::format("{{youngs_modulus = {:g} Pa, density = {:g} kg/m^3}}",
                                            m.youngs_modulus, m.density),
         fmt::format("the wave speeds (c_D = {:g} m/s, c_S = {:g} m/s, docs/theory.md E1) must be finite and "
                     "positive: the modulus over the density is out of range of a double",
                     w.dilatational, w.shear));
  }
  if (!(std::isfinite(s.dt) && s.dt > 0))
    fail("time.cfl", c.time.cfl,
         fmt::format("the time step dt = {:g} s (docs/theory.md E6, from grid.cell_size = {:g} m) must be finite "
                     "and positive", s.dt, c.grid.cell_size));
  if (!(s.steps_exact <= kMostSteps))
    fail("time.end", c.time.end,
         fmt::format("at dt = {:.4g} s (time.cfl x the smallest cell {:g} m / c_D, or the cohesive "
                     "limit, docs/theory.md E6) the run takes {:.4g} steps; at most {:.4g} (2^52 x 1e-6: beyond, "
                     "the time's round-off exceeds the output schedules' tolerance of 1e-6 dt)",
                     s.dt, s.min_cell_size, s.steps_exact, kMostSteps));
  constexpr double kIds = 4294967295.0;  // particle ids and node indices are 32-bit
  if (double(s.particles) > kIds)
    fail("grid.cell_size", c.grid.cell_size,
         fmt::format("the case seeds {} particles; at most 2^32 - 1 (32-bit particle ids)", s.particles));
  if (double(s.nodes) * 3.0 >= 4294967296.0)
    fail("grid.cell_size", c.grid.cell_size,
         fmt::format("the grid has {} nodes; the particle sort numbers 3 per node in 32 bits (at most "
                     "{:.0f}): use a coarser grid or nested levels", s.nodes, 4294967296.0 / 3.0));
  check_memory(c, double(s.memory_bytes) / (1024.0 * 1024.0), "the case",
               " (memory_estimate_mib: particles, grid fields, interfaces)");
}

}  // namespace

void check_grid_limits(const Case& c) {
  // At least the nodes of a uniform grid of the coarsest cells (graded and nested grids hold
  // more), counted without building the grid: a grid of 2e9 cells along one axis is refused
  // before its axes are allocated.
  const double h0 = c.grid.refined() ? c.grid.coarse_cell_size : c.grid.cell_size;
  const double nodes = (std::round((c.grid.max[0] - c.grid.min[0]) / h0) + 1.0) *
                       (std::round((c.grid.max[1] - c.grid.min[1]) / h0) + 1.0);
  if (nodes * 3.0 >= 4294967296.0)
    fail("grid.cell_size", c.grid.cell_size,
         fmt::format("the grid has at least {:.0f} nodes; the particle sort numbers 3 per node in 32 bits "
                     "(at most {:.0f}): use a coarser grid or nested levels", nodes, 4294967296.0 / 3.0));
  // The particles on a uniform grid, without a walk: the plain rectangles' exactly, every other
  // body's at least (seed_points_at_least: areas and perimeters), so at least the case's.
  // Past the 32-bit ids, refused as check_run_limits would; with the grid, within the memory.
  double particles = 0.0;
  bool exact = true;
  if (!c.grid.refined()) {
    const double ppc = c.grid.particles_per_cell, h = c.grid.cell_size;
    for (const BodySpec& b : c.bodies) {
      if (b.plain_rectangle()) {
        particles += std::round((b.max[0] - b.min[0]) / h) * std::round((b.max[1] - b.min[1]) / h) * ppc * ppc;
      } else {
        exact = false;
        particles += seed_points_at_least(b.region, h / ppc);
      }
    }
    if (particles > 4294967295.0)
      fail("grid.cell_size", c.grid.cell_size,
           fmt::format("the case seeds {}{:.0f} particles; at most 2^32 - 1 (32-bit particle ids)",
                       exact ? "" : "at least ", particles));
  }
  const double grid_mib = nodes * double(field_array_count() * sizeof(double)) / (1024.0 * 1024.0);
  check_memory(c, grid_mib,
               fmt::format("the grid alone (at least {:.0f} nodes, grid.cell_size = {:g} m)", nodes,
                           c.grid.cell_size),
               "");
  // A damped material's particles carry the Kelvin-Voigt stress too.
  const bool damped = std::any_of(c.materials.begin(), c.materials.end(),
                                  [](const ElasticMaterial& m) { return m.kelvin_voigt > 0.0; });
  if (particles > 0.0)
    check_memory(c, grid_mib + particles * double(Particles::bytes_per_particle(damped) + 12) / (1024.0 * 1024.0),
                 fmt::format("the grid with its particles ({} {:.0f} particles, at least {:.0f} nodes, "
                             "grid.cell_size = {:g} m)",
                             exact ? "exactly" : "at least", particles, nodes, c.grid.cell_size),
                 "");
}

void check_memory_before_seeding(const Case& c) {
  const double bytes = memory_bytes_before_seeding(c);
  if (bytes > 0.0)
    check_memory(c, bytes / (1024.0 * 1024.0), "the case",
                 " (memory_estimate_mib before any seed point is walked: particles, grid fields, interfaces)");
}

// solver.mass = "averaged" (solver/consistent_mass.hpp) on what it was derived and checked
// for: one grid level, no velocity region, no interface (the cohesive forces, ties and contact act through the
// lumped mass of their face nodes, and the levels' transitions condense lumped masses).
void check_mass_matrix(const Case& c) {
  if (c.solver.mass != MassMatrix::averaged) return;
  if (c.grid.nested)
    fail("solver.mass", "\"averaged\"",
         "needs one grid level: grid.refinement = \"nested\" runs with the lumped mass (solver.mass = \"lumped\")");
  // A velocity region prescribes its nodes' velocity along d after the grid update: with the
  // averaged mass its reaction would already have spread through the solves (a [boundary]
  // edge's nodes are instead known values of the solves, solver/consistent_mass.hpp).
  if (!c.loads.velocity_regions.empty())
    fail("solver.mass", "\"averaged\"",
         fmt::format("is not available with a velocity region ([loads.{}]): velocity regions run with "
                     "the lumped mass (solver.mass = \"lumped\")",
                     c.loads.velocity_regions.front().name));
  if (!c.interfaces.empty())
    fail("solver.mass", "\"averaged\"",
         fmt::format("is not available with an interface ([interface.{}]): interfaces and cracks run with "
                     "the lumped mass (solver.mass = \"lumped\")",
                     c.interface_names.front()));
}

void check_case_consistency(Case& c) {
  check_mass_matrix(c);
  check_boundary_conflicts(c);
  check_touching_bodies(c);
  if (c.grid.nested) check_nested_support(c);  // what the set-up would refuse, refused here
  const CaseSummary s = summarize(c);
  check_run_limits(c, s);
  warn_long_run(c, s);
  warn_ricker_resolution(c);
}

}  // namespace rupture
