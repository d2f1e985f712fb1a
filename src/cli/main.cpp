// rupture/cli/main.cpp
// The `rupture` command line:
//   rupture check CASE.toml [--set key=value ...]   validate and print derived quantities
//   rupture check --explain [KEY]   the description of an input key or table (no case file)
//   rupture docs --input            the input reference as Markdown (docs/input.md)
//   rupture run   CASE.toml -o DIR [--set key=value ...] [--quiet] [--checkpoint-interval T]
//                 [--overwrite] [--no-rebalance]
//   rupture resume DIR [--quiet] [--checkpoint-interval T]   continue from DIR's last checkpoint
//   rupture sweep CASE.toml -o DIR --vary KEY=V1,V2,... [--vary ...] [--set ...] [-j K]
//                 [--threads N] [--checkpoint-interval T] [--quiet]   parameter study
//                 (run/sweep.hpp): DIR/<run>/ and DIR/summary.csv; resumable
//   rupture plot  DIR [--compare DIR2 ...] [--labels A B ...]   figures into DIR/figures/
//                 (python/rupture_plot.py with Debian's /usr/bin/python3: numpy, matplotlib,
//                 h5py; RUPTURE_PYTHON overrides the interpreter)
// Exit codes: 0 success, 1 bad input (also: an output directory holding another run without
// --overwrite, no usable checkpoint to resume), 2 the run went unstable, 3 I/O failure (the
// message names the file and the operating system's reason) or other failure, 4 interrupted by
// SIGINT/SIGTERM after writing a checkpoint (the message says how to resume).
#include <omp.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <sstream>

#include "io/law_registry.hpp"
#include "core/errors.hpp"
#include "core/fp_mode.hpp"
#include "io/case_toml.hpp"
#include "run/checkpoint.hpp"
#include "core/fault_injection.hpp"
#include "parallel/agreement.hpp"
#include "parallel/comm.hpp"
#include "parallel/rank_plan.hpp"
#include "io/input_schema.hpp"
#include "io/text_limits.hpp"
#include "run/driver.hpp"
#include "run/step_cost.hpp"
#include "run/sweep.hpp"
#include "solver/state.hpp"
#include "solver/summary.hpp"

using namespace rupture;

namespace {
// A length in the unit that suits it (um, mm or m): laboratory and kilometre-scale cases alike.
std::string show_length(double m) {
  const double a = std::fabs(m);
  if (a > 0.0 && a < 1e-3) return fmt::format("{:.4g} um", 1e6 * m);
  if (a > 0.0 && a < 1.0) return fmt::format("{:.4g} mm", 1e3 * m);
  return fmt::format("{:.4g} m", m);
}
}  // namespace

namespace {

void print_check(const std::string& path, const Case& c) {
  const CaseSummary s = summarize(c);
  fmt::print("case: {}{}\n", path, c.title.empty() ? "" : " (" + c.title + ")");
  fmt::print("plane {}, scheme {}, flip {:g}\n", c.plane == PlaneMode::strain ? "strain" : "stress",
             scheme_name(c.solver.scheme), c.solver.flip);
  for (std::size_t k = 0; k < c.materials.size(); ++k) {
    const WaveSpeeds& w = s.speeds[k];
    fmt::print(
        "material {}: c_D = {:.1f} m/s, c_S = {:.1f} m/s, c_R = {:.1f} m/s (approx. {:.1f}), "
        "sqrt(2) c_S = {:.1f} m/s\n",
        c.materials[k].name, w.dilatational, w.shear, w.rayleigh, w.rayleigh_approx,
        std::sqrt(2.0) * w.shear);
  }
  for (std::size_t b = 0; b < c.bodies.size(); ++b)
    fmt::print("body {} (field {} \"{}\"): {} particles\n", c.bodies[b].name, c.bodies[b].field,
               c.field_names[std::size_t(c.bodies[b].field)],
               s.particles_per_body[b]);
  fmt::print("dt={:.6e}\n", s.dt);
  fmt::print("dt_cfl_limit={:.6e}\n", s.dt_cfl);
  fmt::print("dt_bulk_limit={:.6e}\n", s.dt_bulk);
  if (s.dt_cohesive > 0) fmt::print("dt_cohesive_limit={:.6e}\n", s.dt_cohesive);
  for (std::size_t k = 0; k < c.interfaces.size(); ++k) {
    const InterfaceSpec& is = c.interfaces[k];
    const Polyline line = is.geometry();
    const double length = line.length();
    const std::string law_text = law_entry(is).describe(is);  // io/law_registry.hpp
    const std::string where =
        line.num_vertices() == 2 && line.y[0] == line.y[1]
            ? fmt::format("on y = {:g} m, x in [{:g}, {:g}] m", line.y[0], line.x[0], line.x[1])
            : fmt::format("along a {} line of {} points, {:g} m long, from ({:g}, {:g}) m",
                          line.closed ? "closed" : "open", line.num_vertices(), length, line.x[0], line.y[0]);
    std::string ties;
    for (const Polyline& tie : is.tie_geometries())
      ties += fmt::format("; bonded along {:g} m from ({:g}, {:g}) m", tie.length(), tie.x[0], tie.y[0]);
    fmt::print("interface {}: {} segments of {} {}; {}, {}{}{}; bodies {} (upper) and {}\n",
               c.interface_names[k], is.segments, show_length(length / is.segments), where, law_name(is.law),
               law_text, is.contact ? fmt::format("; contact, friction {:g}", is.contact_law.friction) : "",
               ties, c.bodies[std::size_t(is.upper_body)].name, c.bodies[std::size_t(is.lower_body)].name);
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

// The run's wall time predicted from a few timed steps of this case on this machine
// (run/step_cost.hpp); the progress line's ETA refines it during the run.
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

std::string plot_script(const char* argv0) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  const fs::path dir = ec ? fs::path(argv0).parent_path() : exe.parent_path();
  for (const fs::path& p : {dir / "rupture_plot.py", dir / "../share/rupture/rupture_plot.py",
                            fs::path(RUPTURE_PLOT_SCRIPT_SOURCE)})
    if (fs::exists(p)) return p.string();
  return {};
}

// Replaces this process by the plotting script; returns only on failure.
int run_plot(const char* argv0, const std::string& dir, const std::vector<std::string>& compare,
             const std::vector<std::string>& labels) {
  const std::string script = plot_script(argv0);
  if (script.empty()) {
    fmt::print(stderr, "error: rupture_plot.py not found next to the executable nor at {}\n",
               RUPTURE_PLOT_SCRIPT_SOURCE);
    return 3;
  }
  const char* env = std::getenv("RUPTURE_PYTHON");
  const std::string python = env && *env ? env
                             : std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3"
                                                                           : "python3";
  std::vector<std::string> args{python, script, dir};
  if (!compare.empty()) {
    args.push_back("--compare");
    args.insert(args.end(), compare.begin(), compare.end());
  }
  if (!labels.empty()) {
    args.push_back("--labels");
    args.insert(args.end(), labels.begin(), labels.end());
  }
  std::vector<char*> cargs;
  for (std::string& a : args) cargs.push_back(a.data());
  cargs.push_back(nullptr);
  execvp(cargs[0], cargs.data());
  fmt::print(stderr, "error: cannot start '{}': {}\n", python, std::strerror(errno));
  return 3;
}

CaseSource read_case_source(const std::string& path, const std::vector<std::string>& overrides) {
  return CaseSource{read_bounded_file(path, kMaxCaseBytes, "case file"), path, overrides};
}

// rupture check --explain KEY: the schema entry (io/input_schema.hpp), or exit code 1 with the
// documented keys that come close.
int explain(const std::string& key) {
  if (const KeyDoc* e = find_key(key)) {
    fmt::print("{}", explain_key(*e));
    return 0;
  }
  std::string hint;
  for (const std::string& k : similar_keys(key)) hint += "\n  " + k;
  fmt::print(stderr, "error: '{}' is not an input key or table{}\n", key,
             hint.empty() ? "; rupture check --explain lists the tables"
                          : "; did you mean:" + hint);
  return 1;
}

int exit_code(Outcome o) {
  switch (o) {
    case Outcome::completed: return 0;
    case Outcome::unstable: return 2;
    case Outcome::interrupted: return 4;
    case Outcome::io_error:
    case Outcome::error: return 3;
  }
  return 3;
}

// rupture check --ranks N: how a distributed run would split the case (parallel/rank_plan.hpp).
void print_rank_plan(const Case& c, int ranks) {
  const State s = make_state(c);
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

}  // namespace

int main(int argc, char** argv) {
  rupture::flush_subnormals_to_zero();  // core/fp_mode.hpp: before any other thread exists
  // Under mpirun every process runs this; `rupture run` then steps one case together
  // (parallel/halo.hpp) and rank 0 alone prints and writes (the others' stdout is discarded;
  // the diagnoses every rank shares are printed by rank 0 only).
  const MpiSession mpi(launched_by_mpi());
  const Comm world = Comm::world();
  if (world.rank() > 0 && !std::freopen("/dev/null", "w", stdout)) return 3;
  const bool quiet_errors = world.rank() > 0;
  try {
    arm_fault_from_environment(world.rank());  // tests of failure paths (core/fault_injection.hpp)
  } catch (const InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  CLI::App app{"rupture: dynamic fracture with GIMP and cohesive zones"};
  app.require_subcommand(1);
  std::string case_path, out_dir;
  std::vector<std::string> overrides;
  bool quiet = false;

  auto* check = app.add_subcommand("check", "validate a case and print derived quantities");
  // CASE is required unless --explain is given (checked after parsing).
  auto* check_case = check->add_option("case", case_path, "case file (TOML)");
  check->add_option("--set", overrides, "override an input key: dotted.key=value");
  int check_ranks = 0;
  check->add_option("--ranks", check_ranks,
                    "print how N processes would split the case: blocks, particles and shared "
                    "nodes per rank, predicted imbalance")
      ->check(CLI::Range(1, 1 << 20));
  bool no_timing = false;
  check->add_flag("--no-timing", no_timing,
                  "skip the few timed steps behind measured_step_seconds= and predicted_wall_seconds=");
  std::string explain_path;
  auto* explain_opt =
      check->add_option("--explain", explain_path,
                        "describe an input key or table (unit, default, range, example), e.g. "
                        "time.cfl or interface.weak_plane.sigma_max; no KEY: the top level")
          ->expected(0, 1);

  auto* docs = app.add_subcommand("docs", "print reference documentation");
  bool docs_input = false;
  docs->add_flag("--input", docs_input, "every input table and key as Markdown (docs/input.md)")
      ->required();

  auto* run = app.add_subcommand("run", "run a case");
  run->add_option("case", case_path, "case file (TOML)")->required();
  run->add_option("-o,--output", out_dir, "output directory")->required();
  run->add_option("--set", overrides, "override an input key: dotted.key=value");
  run->add_flag("-q,--quiet", quiet, "no progress line");
  double checkpoint_interval = 0.0;
  long stop_after_steps = 0;
  bool overwrite = false;
  run->add_option("--checkpoint-interval", checkpoint_interval,
                  "write a checkpoint every T seconds of simulated time (rupture resume DIR)")
      ->check(CLI::NonNegativeNumber);
  run->add_flag("--overwrite", overwrite, "delete another run's files in the output directory");
  bool no_rebalance = false;
  run->add_flag("--no-rebalance", no_rebalance,
                "under mpirun: keep the split of t = 0 (no re-split when the measured load drifts)");
  // Tests: stop after N steps as if interrupted (checkpoint written, exit code 4).
  run->add_option("--stop-after-steps", stop_after_steps)->group("");

  std::string resume_dir;
  auto* resume = app.add_subcommand("resume", "continue a run from its last checkpoint");
  resume->add_option("dir", resume_dir, "run directory")->required()->check(CLI::ExistingDirectory);
  resume->add_flag("-q,--quiet", quiet, "no progress line");
  resume->add_option("--checkpoint-interval", checkpoint_interval,
                     "change the checkpoint interval (default: the run's)")
      ->check(CLI::NonNegativeNumber);
  resume->add_option("--stop-after-steps", stop_after_steps)->group("");
  resume->add_flag("--no-rebalance", no_rebalance, "under mpirun: keep the split made at the resume");

  SweepOptions sweep_opt;
  std::vector<std::string> vary;
  auto* sweep = app.add_subcommand("sweep", "run a case for every combination of --vary values");
  sweep->add_option("case", sweep_opt.case_path, "case file (TOML)")->required()->check(CLI::ExistingFile);
  sweep->add_option("-o,--output", sweep_opt.dir, "sweep directory")->required();
  sweep->add_option("--vary", vary, "KEY=V1,V2,...: values of an input key (repeat for more keys)")
      ->required();
  sweep->add_option("--set", sweep_opt.sets, "override an input key in every run: dotted.key=value");
  sweep->add_option("-j,--jobs", sweep_opt.jobs, "runs at a time (default 1)")->check(CLI::PositiveNumber);
  sweep->add_option("--threads", sweep_opt.threads,
                    "threads in all, split between the runs (default: the machine's)")
      ->check(CLI::PositiveNumber);
  sweep->add_option("--checkpoint-interval", sweep_opt.checkpoint_interval,
                    "checkpoint every T seconds of simulated time in each run")
      ->check(CLI::NonNegativeNumber);
  sweep->add_flag("-q,--quiet", sweep_opt.quiet, "no line per run");

  std::string plot_dir;
  std::vector<std::string> compare, labels;
  auto* plot = app.add_subcommand("plot", "write the figures of a finished run into DIR/figures/");
  plot->add_option("dir", plot_dir, "run directory")->required()->check(CLI::ExistingDirectory);
  plot->add_option("--compare", compare, "more run directories to overlay on crack_tip.png (on a sweep: more sweeps, one map)")
      ->check(CLI::ExistingDirectory);
  plot->add_option("--labels", labels, "legend labels, one per run");

  CLI11_PARSE(app, argc, argv);
  if (docs->parsed()) {
    fmt::print("{}", input_reference_markdown());
    return 0;
  }
  if (check->parsed() && explain_opt->count() > 0) return explain(explain_path);
  if (check->parsed() && check_case->count() == 0)
    return app.exit(CLI::RequiredError(check_case->get_name()));
  if (plot->parsed()) return run_plot(argv[0], plot_dir, compare, labels);
  if (sweep->parsed()) {
    try {
      for (const std::string& v : vary) sweep_opt.axes.push_back(parse_vary(v));
      std::error_code ec;
      const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
      sweep_opt.exe = ec ? std::string(argv[0]) : self.string();
      return run_sweep(sweep_opt);
    } catch (const InputError& e) {
      fmt::print(stderr, "error: {}\n", e.what());
      return 1;
    } catch (const std::exception& e) {
      fmt::print(stderr, "error: {}\n", e.what());
      return 3;
    }
  }

  try {
    auto warn = [&](const Case& c) {
      if (quiet_errors) return;
      for (const std::string& w : c.warnings) fmt::print(stderr, "warning: {}\n", w);
    };
    if (check->parsed()) {
      const Case c = load_case(case_path, overrides);
      warn(c);
      print_check(case_path, c);
      if (check_ranks > 0) print_rank_plan(c, check_ranks);
      if (!no_timing) print_predicted_time(c);
      return 0;
    }
    RunOptions options;
    options.progress = !quiet;
    options.checkpoint_interval = checkpoint_interval;
    options.stop_after_steps = stop_after_steps;
    options.rebalance = !no_rebalance;
    if (resume->parsed()) {
      out_dir = resume_dir;
      options.resume = true;
      options.source = read_checkpoint_source(checkpoint_path(resume_dir));
      fmt::print("resuming run in {}\n", resume_dir);
    } else {
      options.source = read_case_source(case_path, overrides);
      options.overwrite = overwrite;
    }
    options.output_dir = out_dir;
    options.comm = world;
    const Case c = parse_case(options.source.text, options.source.overrides, options.source.origin);
    // A checkpoint must not depend on files that can change or vanish before `rupture resume`:
    // with table_file tables it stores the merged input with the tables inline (exact: the
    // echo writes every number so that it reads back to the same double).
    if (!resume->parsed() && c.read_table_files)
      options.source = CaseSource{c.input_toml, options.source.origin, {}};
    warn(c);
    print_check(options.source.origin, c);
    const RunResult r = run_case(c, options);
    fmt::print("status={}\n", r.status);
    fmt::print("stop_reason={}\n", r.stop_reason);
    fmt::print("steps={}\n", r.steps);
    fmt::print("simulated_time={:.6e}\n", r.simulated_time);
    fmt::print("wall_seconds={:.3f}\n", r.wall_seconds);
    fmt::print("particle_updates_per_second={:.4e}\n", r.particle_updates_per_second);
    fmt::print("cohesive_seconds={:.3f}\n", r.cohesive_seconds);
    if (r.ranks > 1) {  // distributed: how the particles were split, and how often they moved
      fmt::print("ranks={}\n", r.ranks);
      fmt::print("particles_per_rank={}\n", fmt::join(r.particles_per_rank, ","));
      fmt::print("particles_per_rank_end={}\n", fmt::join(r.particles_per_rank_end, ","));
      fmt::print("migrations={}\n", r.migrations);
      fmt::print("rebalances={}\n", r.rebalances);
      fmt::print("exchange_bytes_per_rank_per_step={:.0f}\n", r.exchange_bytes_per_step);
      fmt::print("exchange_seconds={:.3f}\n", r.exchange_seconds);
      fmt::print("peak_memory_mib_per_rank={:.0f}\n", fmt::join(r.peak_memory_per_rank, ","));
    }
    if (!r.peak_memory_per_rank.empty())
      fmt::print("peak_memory_mib={:.0f}\n",
                 *std::max_element(r.peak_memory_per_rank.begin(), r.peak_memory_per_rank.end()));
    fmt::print("energy_balance_error={:.4e}\n", r.energy_balance_error);
    fmt::print("energy_balance_error_final={:.4e}\n", r.energy_balance_error_final);
    if (!r.cracks.empty()) {
      const CrackSummary& k = r.cracks.front();
      fmt::print("crack.initiation_time={:.6e}\n", k.initiation_time);
      fmt::print("crack.sustained_speed={:.1f}\n", k.sustained_speed);
      {  // against the lower body's material (run.json has both sides)
        const WaveSpeeds w = wave_speeds(
            c.materials[std::size_t(c.bodies[std::size_t(c.interfaces[0].lower_body)].material)], c.plane);
        fmt::print("crack.sustained_speed_over_cR={:.4f}\n", k.sustained_speed / w.rayleigh);
        fmt::print("crack.sustained_speed_over_cS={:.4f}\n", k.sustained_speed / w.shear);
      }
      fmt::print("crack.peak_speed={:.1f}\n", k.peak_speed);
      fmt::print("crack.intersonic_time={:.6e}\n", k.intersonic_time);
      fmt::print("crack.daughter_crack_time={:.6e}\n", k.daughter_time);
      fmt::print("crack.final_tip={:.6e}\n", k.final_tip);
      fmt::print("crack.final_cohesive_zone_length={:.6e}\n", k.final_cohesive_zone);
      fmt::print("crack.final_traction_zone_length={:.6e}\n", k.final_traction_zone);
      fmt::print("crack.cohesive_zone_definition={}\n", CrackTracker::kCohesiveZoneDefinition);
      fmt::print("crack.traction_zone_definition={}\n", CrackTracker::kTractionZoneDefinition);
      fmt::print("crack.end_reached_time={:.6e}\n", k.end_reached_time);
      fmt::print("crack.regime={}\n", k.regime);
      fmt::print("crack.steady_begin={:.6e}\n", k.steady_begin);
      fmt::print("crack.steady_end={:.6e}\n", k.steady_end);
      fmt::print("crack.last_window_speed={:.1f}\n", k.last_window_speed);
      fmt::print("crack.arrested={}\n", k.arrested);
      fmt::print("crack.arrest_time={:.6e}\n", k.arrest_time);
      fmt::print("crack.arrest_s={:.6e}\n", k.arrest_s);
      // SPEC E12: the shear Mach angle read at the snapshot times (-1: not measured).
      fmt::print("crack.mach_readings={}\n", k.mach_readings);
      fmt::print("crack.mach_angle={:.2f}\n", k.mach_angle);
      fmt::print("crack.mach_angle_spread={:.2f}\n", k.mach_angle_spread);
      fmt::print("crack.mach_angle_left={:.2f}\n", k.mach_angle_left);
      fmt::print("crack.mach_angle_right={:.2f}\n", k.mach_angle_right);
      fmt::print("crack.mach_speed={:.1f}\n", k.mach_speed);
      // Every interface by name, in input order (the first also under crack.* above).
      for (std::size_t i = 0; i < r.cracks.size(); ++i) {
        const CrackSummary& q = r.cracks[i];
        const std::string& n = c.interface_names[i];
        fmt::print("crack.{}.initiation_time={:.6e}\n", n, q.initiation_time);
        fmt::print("crack.{}.initiation_s={:.6e}\n", n, q.initiation_s);
        fmt::print("crack.{}.sustained_speed={:.1f}\n", n, q.sustained_speed);
        fmt::print("crack.{}.back_speed={:.1f}\n", n, q.back_speed);
        fmt::print("crack.{}.final_tip_s={:.6e}\n", n, q.final_tip_s);
        fmt::print("crack.{}.regime={}\n", n, q.regime);
        fmt::print("crack.{}.last_window_speed={:.1f}\n", n, q.last_window_speed);
        fmt::print("crack.{}.arrested={}\n", n, q.arrested);
        fmt::print("crack.{}.mach_angle={:.2f}\n", n, q.mach_angle);
        fmt::print("crack.{}.mach_speed={:.1f}\n", n, q.mach_speed);
      }
    }
    fmt::print("output={}\n", out_dir);
    if (quiet_errors) {
    } else if (r.outcome == Outcome::interrupted) {
      fmt::print(stderr, "{}\n", r.message);
    } else if (!r.ok) {
      fmt::print(stderr, "error: {}\n", r.message);
    }
    return exit_code(r.outcome);
  } catch (const InputError& e) {  // the same on every rank of a distributed run
    if (!quiet_errors) fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  } catch (const AgreedFailure& e) {  // every rank holds it (parallel/agreement.hpp)
    if (!quiet_errors) fmt::print(stderr, "error: {}\n", e.what());
    return e.exit_code();
  } catch (const std::exception& e) {
    if (world.distributed()) {  // one rank's own failure: say which, and stop the others
      fmt::print(stderr, "error: rank {}: {}\n", world.rank(), e.what());
      world.abort(3);
    }
    fmt::print(stderr, "error: {}\n", e.what());
    return 3;
  }
}
