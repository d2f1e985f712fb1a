// rupture/cli/print_check.cpp
#include "cli/print_check.hpp"

#include <omp.h>

#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <vector>

#include "input/law_registry.hpp"
#include "parallel/rank_plan.hpp"
#include "run/step_cost.hpp"
#include "solver/run_state.hpp"
#include "solver/summary.hpp"

namespace rupture {
namespace {

// A length in the unit that suits it (um, mm or m): laboratory and kilometre-scale cases alike.
std::string show_length(double m) {
  const double a = std::fabs(m);
  if (a > 0.0 && a < 1e-3) return fmt::format("{:.4g} um", 1e6 * m);
  if (a > 0.0 && a < 1.0) return fmt::format("{:.4g} mm", 1e3 * m);
  return fmt::format("{:.4g} m", m);
}

}  // namespace

void print_check(const std::string& path, const Case& c) {
  const CaseSummary s = summarize(c);
  fmt::print("case: {}{}\n", path, c.title.empty() ? "" : " (" + c.title + ")");
  fmt::print("plane {}, scheme {}, flip {:g}{}\n", c.plane == PlaneMode::strain ? "strain" : "stress",
             scheme_name(c.solver.scheme), c.solver.flip,
             c.solver.mass == MassMatrix::averaged ? ", averaged mass" : "");
  for (std::size_t k = 0; k < c.materials.size(); ++k) {
    const WaveSpeeds& w = s.speeds[k];
    fmt::print(
        "material {}: c_D = {:.1f} m/s, c_S = {:.1f} m/s, c_R = {:.1f} m/s (approx. {:.1f}), "
        "sqrt(2) c_S = {:.1f} m/s; E = {:.6g} Pa, nu = {:.6g}, rho = {:g} kg/m^3\n",
        c.materials[k].name, w.dilatational, w.shear, w.rayleigh, w.rayleigh_approx,
        std::sqrt(2.0) * w.shear, c.materials[k].youngs_modulus, c.materials[k].poisson_ratio,
        c.materials[k].density);
  }
  for (std::size_t b = 0; b < c.bodies.size(); ++b)
    fmt::print("body {} (field {} \"{}\"): {} particles\n", c.bodies[b].name, c.bodies[b].field,
               c.field_names[std::size_t(c.bodies[b].field)],
               s.particles_per_body[b]);
  for (std::size_t k = 0; k < c.interfaces.size(); ++k)
    for (const int f : c.interfaces[k].branch_fields)
      fmt::print("field {} \"{}\": kept for the wedge of a split of interface {} (no particles until then)\n", f,
                 c.field_names[std::size_t(f)], c.interface_names[k]);
  fmt::print("dt={:.6e}\n", s.dt);
  fmt::print("dt_cfl_limit={:.6e}\n", s.dt_cfl);
  fmt::print("dt_bulk_limit={:.6e}\n", s.dt_bulk);
  if (s.dt_cohesive > 0) fmt::print("dt_cohesive_limit={:.6e}\n", s.dt_cohesive);
  for (std::size_t k = 0; k < c.interfaces.size(); ++k) {
    const InterfaceSpec& is = c.interfaces[k];
    const Polyline line = is.geometry();
    const double length = line.length();
    const std::string law_text = law_entry(is).describe(is);  // input/law_registry.hpp
    const std::string where =
        line.num_vertices() == 2 && line.y[0] == line.y[1]
            ? fmt::format("on y = {:g} m, x in [{:g}, {:g}] m", line.y[0], line.x[0], line.x[1])
            : fmt::format("along a {} line of {} points, {:g} m long, from ({:g}, {:g}) m",
                          line.closed ? "closed" : "open", line.num_vertices(), length, line.x[0], line.y[0]);
    std::string ties;
    for (const Polyline& tie : is.tie_geometries())
      ties += fmt::format("; bonded along {:g} m from ({:g}, {:g}) m", tie.length(), tie.x[0], tie.y[0]);
    if (is.nucleation_strength > 0.0)  // solver/crack_nucleation.hpp
      ties += fmt::format("; intact (bonded over itself) until the normal stress across it reaches {:g} Pa",
                          is.nucleation_strength);
    // Faces that change body along the line (a T-junction): each body from its arc length on.
    std::string faces;
    for (const auto& [side, list] : {std::pair{"upper", &is.upper_faces}, std::pair{"lower", &is.lower_faces}}) {
      if (list->empty()) continue;
      faces += fmt::format("; {} face on", side);
      for (const FaceField& f : *list)
        faces += fmt::format(" {} from s = {:g} m", c.bodies[std::size_t(f.body)].name, f.from);
    }
    fmt::print("interface {}: {} segments of {} {}; {}, {}{}{}; bodies {} (upper) and {}{}\n",
               c.interface_names[k], is.segments, show_length(length / is.segments), where, law_entry(is).name,
               law_text, is.contact ? fmt::format("; contact, friction {:g}", is.contact_law.friction) : "",
               ties, c.bodies[std::size_t(is.upper_body)].name, c.bodies[std::size_t(is.lower_body)].name, faces);
  }
  if (c.grid.refined()) {
    fmt::print("refined grid: {} levels, level 0 = {:g} m, finest = {:g} m; smallest cell {:g} m\n",
               s.level_sizes.size(), c.grid.coarse_cell_size, c.grid.cell_size, s.min_cell_size);
    fmt::print("refinement={} ({})\n", c.grid.nested ? "nested" : "graded",
               c.grid.nested ? "nested levels, each over its own boxes, transition nodes"
                             : "graded tensor-product grid, fine rows and columns across the plate");
    if (c.grid.nested)
      fmt::print("subcycling={} ({})\n", c.time.subcycling == Subcycling::levels ? "levels" : "none",
                 c.time.subcycling_given ? "time.subcycling as given"
                 : c.time.subcycling == Subcycling::levels
                     ? "the default: per-level time steps, verified for this case"
                     : "the default here: per-level steps are not verified with [loads], [absorbing], "
                       "USL/USF or interfaces on two levels");
    for (std::size_t L = 0; L < s.level_sizes.size(); ++L)
      fmt::print("level {} ({:g} m): cells_level_{}={} particles_level_{}={}\n", L, s.level_sizes[L],
                 L, s.cells_per_level[L], L, s.particles_per_level[L]);
  }
  fmt::print("cells={}\n", s.cells);
  fmt::print("nodes={}\n", s.nodes);
  fmt::print("field_nodes={} ({} fields; {:.2f} x the grid)\n", s.field_nodes, s.fields,
             double(s.field_nodes) / double(s.nodes));
  fmt::print("ghost_cells={} (margin {} for free surfaces to move into)\n", s.ghost_cells,
             show_length(c.grid.margin));
  fmt::print("particles={}\n", s.particles);
  fmt::print("steps={}\n", s.steps);
  fmt::print("memory_estimate_mib={:.1f}\n", double(s.memory_bytes) / (1024.0 * 1024.0));
}

void print_rank_plan(const Case& c, int ranks) {
  const RunState s = make_run_state(c);
  const RankPlan plan = plan_ranks(s, ranks);
  if (plan.levels.size() > 1)
    fmt::print("ranks={} (level {}'s cells over the plate bisected by the work of every level's "
               "particles; rank r takes the same rectangle on every level, its sides on a coarser "
               "level's lines below)\n",
               ranks, plan.cut_level);
  else
    fmt::print("ranks={} (the grid's cells bisected by particle count)\n", ranks);
  std::vector<std::size_t> particles(std::size_t(ranks), 0);
  std::vector<long> shared(std::size_t(ranks), 0);
  for (std::size_t l = 0; l < plan.levels.size(); ++l) {
    const LevelSplit& L = plan.levels[l];
    fmt::print("{}{} x {} cells{}, imbalance {:.4f}, reach up to {} nodes beyond a block\n",
               plan.levels.size() > 1 ? fmt::format("level {}: ", l) : std::string("grid: "), L.cols,
               L.rows, L.period > 1 ? fmt::format(", one step every {} finest", L.period) : "",
               L.split.imbalance(), L.width());
    for (int r = 0; r < ranks; ++r) {
      const CellBlock& b = L.split.block[std::size_t(r)];
      fmt::print("  rank {}: cells [{}, {}) x [{}, {}), particles {}, shared nodes {}\n", r, b.c0,
                 b.c1, b.r0, b.r1, L.split.particles[std::size_t(r)],
                 L.split.shared_nodes[std::size_t(r)]);
      particles[std::size_t(r)] += L.split.particles[std::size_t(r)];
      shared[std::size_t(r)] += L.split.shared_nodes[std::size_t(r)];
    }
  }
  const auto join = [](const auto& v, const char* f) {
    std::string out;
    for (const auto& x : v) {
      if (!out.empty()) out += ',';
      out += fmt::format(fmt::runtime(f), x);
    }
    return out;
  };
  fmt::print("particles_per_rank={}\n", join(particles, "{}"));
  fmt::print("work_per_rank={} (particle-updates per finest step)\n", join(plan.work, "{:.0f}"));
  fmt::print("shared_nodes_per_rank={}\n", join(shared, "{}"));
  fmt::print("exchange_bytes_per_rank={} (sent to the neighbours per finest step: {} values or "
             "more per halo node and field)\n",
             join(plan.exchange_bytes, "{:.0f}"), kExchangedValues);
  fmt::print("predicted_imbalance={:.4f} (largest work / mean - 1)\n", plan.imbalance());
}

void print_predicted_time(const Case& c) {
  const CaseSummary s = summarize(c);
  const StepCost cost = measure_step_cost(c);
  fmt::print("measured_setup_seconds={:.3f}\n", cost.setup_seconds);
  fmt::print("measured_step_seconds={:.4e} (mean of {} steps after a warm-up one, {} threads)\n",
             cost.step_seconds, cost.steps, omp_get_max_threads());
  fmt::print("measured_ns_per_particle_update={:.1f}\n", cost.ns_per_particle_update);
  if (!cost.level_periods.empty())
    fmt::print("level_periods={} (finest steps per step of levels 0..{}, time.subcycling = \"levels\"; "
               "{:.0f} particle-updates per finest step instead of {})\n",
               fmt::join(cost.level_periods, ","), cost.level_periods.size() - 1,
               cost.updates_per_finest_step, cost.particles);
  if (cost.snapshot_seconds > 0 || cost.interface_seconds > 0)
    fmt::print("measured_output_seconds={:.3f} per snapshot, {:.3f} per set of interface profiles\n",
               cost.snapshot_seconds, cost.interface_seconds);
  fmt::print("predicted_wall_seconds={:.1f} (set-up + {} steps + snapshots and interface profiles)\n",
             predicted_wall_seconds(cost, c, s.steps), s.steps);
}

}  // namespace rupture
