// rupture-case-bench: time to solution of a whole case on the graded tensor-product grid and on
// nested levels (grid/nested.hpp, solver/nested_state.hpp), with the crack each gives (theory §4:
// E10 initiation, E11 speeds), no output written. For issue "Speed": same physics, fewer
// particle-updates.
//   rupture-case-bench CASE [--set key=value ...] [--realization graded|nested|both] [--threads T]
// Prints, per realization, key=value lines: particles, steps, wall_seconds,
// particle_updates_per_second, initiation_us, sustained_speed, last_window_speed (interface 0).
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <string>
#include <vector>

#include "core/fp_mode.hpp"
#include "cohesive/crack_tip.hpp"
#include "input/case_toml.hpp"
#include "solver/nested_state.hpp"
#include "solver/step.hpp"
#include "solver/summary.hpp"

using namespace rupture;

namespace {

struct Outcome {
  std::size_t particles = 0;
  long steps = 0;
  double wall = 0.0, updates = 0.0;
  bool has_crack = false;
  CrackSummary crack;
};

// Samples interface 0's tip at multiples of the case's crack interval (as the driver does).
class CrackClock {
 public:
  CrackClock(const Case& c, const CohesiveInterface* ci, double h)
      : interval_(c.output.crack_sample_interval > 0 ? c.output.crack_sample_interval : 0.02e-6) {
    if (!ci) return;
    tracker_ = CrackTracker(*ci, 2.0 * h, h);
    tracker_.sample(*ci, 0.0);
    next_ = interval_;
  }
  void after_step(const CohesiveInterface* ci, double t, double eps) {
    if (!ci) return;
    while (next_ <= t + eps) {
      tracker_.sample(*ci, std::min(next_, t));
      next_ += interval_;
    }
  }
  CrackSummary summary(const CohesiveInterface& ci, const WaveSpeeds& w) const { return tracker_.summarize(ci, w); }

 private:
  double interval_, next_ = 0.0;
  CrackTracker tracker_;
};

Outcome run_graded(const Case& c, const WaveSpeeds& w) {
  Outcome o;
  const auto t0 = std::chrono::steady_clock::now();
  State s = make_state(c);
  o.particles = s.particles.size();
  const CohesiveInterface* ci = s.interfaces.empty() ? nullptr : &s.interfaces[0];
  CrackClock clock(c, ci, s.grid.cell_size());
  const double eps = 1e-6 * s.dt;
  while (s.time < c.time.end - eps) {
    s.dt_cap = c.time.end - s.time;
    step(s);
    o.updates += double(s.particles.size());
    clock.after_step(ci, s.time, eps);
  }
  o.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  o.steps = s.step;
  if (ci) o.has_crack = true, o.crack = clock.summary(*ci, w);
  return o;
}

Outcome run_nested(const Case& c, const WaveSpeeds& w) {
  Outcome o;
  const auto t0 = std::chrono::steady_clock::now();
  RunState n = make_nested_state(c);
  o.particles = held_particles(n);
  const CohesiveInterface* ci = nullptr;
  double h = 0;
  for (const State& s : n.levels)
    if (!s.interfaces.empty()) ci = &s.interfaces[0], h = s.grid.x.h;
  for (std::size_t l = 0; l < n.levels.size(); ++l)
    fmt::print("nested_level_{}_particles={} (cell {:g} m)\n", l, n.levels[l].particles.size(), n.levels[l].grid.x.h);
  CrackClock clock(c, ci, h);
  const double eps = 1e-6 * n.dt;
  while (n.time < c.time.end - eps) {
    n.dt_cap = c.time.end - n.time;
    step(n);
    o.updates += double(held_particles(n));
    clock.after_step(ci, n.time, eps);
  }
  o.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  o.steps = n.step;
  fmt::print("nested_migrations={}\n", n.migrations);
  if (ci) o.has_crack = true, o.crack = clock.summary(*ci, w);
  return o;
}

void report(const char* name, const Outcome& o) {
  fmt::print("realization={}\nparticles={}\nsteps={}\nwall_seconds={:.2f}\nparticle_updates_per_second={:.4g}\n",
             name, o.particles, o.steps, o.wall, o.updates / o.wall);
  if (o.has_crack)
    fmt::print("initiation_us={:.4f}\nsustained_speed={:.1f}\nlast_window_speed={:.1f}\npeak_speed={:.1f}\n",
               o.crack.initiation_time * 1e6, o.crack.sustained_speed, o.crack.last_window_speed,
               o.crack.peak_speed);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rupture-case-bench: time to solution on the graded grid and on nested levels"};
  std::string path, realization = "both";
  std::vector<std::string> sets;
  int threads = 0;
  app.add_option("case", path, "case file (TOML)")->required();
  app.add_option("--set", sets, "key=value overrides, as rupture run");
  app.add_option("--realization", realization, "graded, nested or both")
      ->check(CLI::IsMember({"graded", "nested", "both"}));
  app.add_option("--threads", threads, "OpenMP threads (0: the default)")->check(CLI::Range(0, 1024));
  CLI11_PARSE(app, argc, argv);
  if (threads > 0) omp_set_num_threads(threads);
  flush_subnormals_to_zero();  // as rupture run does (core/fp_mode.hpp)
  try {
    const Case c = load_case(path, sets);
    const CaseSummary summary = summarize(c);
    WaveSpeeds w{};
    if (!c.interfaces.empty()) w = summary.speeds[std::size_t(c.bodies[std::size_t(c.interfaces[0].lower_body)].material)];
    fmt::print("threads={}\n", omp_get_max_threads());
    if (realization != "nested") report("graded", run_graded(c, w));
    if (realization != "graded") report("nested", run_nested(c, w));
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  return 0;
}
