// rupture-bench: throughput of the elastic GIMP time step on a uniform N x N grid with 2 x 2
// particles per cell (uGIMP, double precision, MUSL, one velocity field), loaded by a
// velocity pulse on the left edge so every phase does real work.
//   rupture-bench --cells N --steps S --threads T [--repeat R]
// Prints a per-phase table (ns per particle-update), the modelled bytes per particle-update
// with the bandwidth they imply against a STREAM-like triad on the same threads, and ends with
//   particle_updates_per_second=<value>   (median over the repeats)
#include <omp.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <fmt/format.h>
#include <vector>

#include "core/fp_mode.hpp"
#include "input/case_toml.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"

using namespace rupture;
using Clock = std::chrono::steady_clock;

namespace {

Case bench_case(int cells) {
  const double h = 1e-3 / 4;  // any size: the cost is per particle
  const double size = h * cells;
  return parse_case(fmt::format(R"(
[materials.homalite]
youngs_modulus = 5.2e9
poisson_ratio = 0.34
density = 1246.0
[grid]
min = [0.0, 0.0]
max = [{0}, {0}]
cell_size = {1}
margin = 0.0  # the bench runs a few steps, not to time.end: two ghost cells are plenty
[bodies.plate]
material = "homalite"
min = [0.0, 0.0]
max = [{0}, {0}]
[time]
end = 1.0
[boundary.impact]
edge = "left"
component = "x"
function = "trapezoid"
velocity = 10.0
rise_time = 1e-7
plateau_time = 1.0
fall_time = 1e-6
)",
                                size, h));
}

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Bytes of particle arrays each phase's loop moves per particle, read + written (8-byte arrays,
// 1-byte field/material ids), read off src/solver/transfer.cpp, stencil_batch.hpp and
// particle_sort.cpp. Every batch of weights reads x, y, half_x, half_y. A written array that
// is not also read costs a read too (write-allocate). Grid arrays are not counted: a strip's
// nodes stay in cache while its particles are scattered.
//   P2G: x y hx hy m V0 vx vy sxx syy sxy + field, material           -> 11 x 8 + 2
//   G2P velocity + re-map: x y hx hy vx vy m + field; writes vx vy    -> 7 x 8 + 1 + 2 x 8
//   stress + move: x y hx hy V0 sxx syy sxy + field, material; writes x y sxx syy sxy; not
//     vx vy (the MUSL pass's finiteness check reads the stress: solver/gather.cpp); strain,
//     sigma_zz and V are derived from the stress, not stored  -> 8 x 8 + 2 + 5 x 8
//   a sort (when one is due: solver/particle_sort.cpp; counted in the timed steps): x y hx hy
//     for the keys, field for the strips' rows, then each of the bytes_per_particle read,
//     written to scratch (write-allocate) and swapped in      -> 4 x 8 + 1 + 3 x 94 per sort
constexpr double kBytesP2G = 11 * 8 + 2;
constexpr double kBytesVelocity = 7 * 8 + 1 + 2 * 8;
constexpr double kBytesStress = 8 * 8 + 2 + 5 * 8;
constexpr double kBytesEachSort = 4 * 8 + 1 + 3 * double(Particles::bytes_per_particle());

// A STREAM-like triad a = b + q c over arrays far larger than the caches, on the same threads:
// the best of `repeat` passes, in GB/s counted as STREAM does (24 bytes per element).
double stream_triad_gb_per_s(std::size_t n, int repeat) {
  std::vector<double> a(n), b(n), c(n);
  const long m = long(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < m; ++i) a[std::size_t(i)] = 0.0, b[std::size_t(i)] = 1.0, c[std::size_t(i)] = 2.0;
  double best = 0.0;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = Clock::now();
    double* pa = a.data();
    const double *pb = b.data(), *pc = c.data();
#pragma omp parallel for schedule(static)
    for (long i = 0; i < m; ++i) pa[i] = pb[i] + 3.0 * pc[i];
    best = std::max(best, 24.0 * double(n) / seconds_since(t0) / 1e9);
  }
  if (a[n / 2] != 7.0) fmt::print("stream check failed\n");
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"rupture-bench: particle-updates per second of the elastic MUSL step"};
  int cells = 256, steps = 20, threads = 0, repeat = 3;
  app.add_option("--cells", cells, "grid cells per direction")->check(CLI::Range(4, 8192));
  app.add_option("--steps", steps, "time steps per repeat")->check(CLI::Range(1, 1000000));
  app.add_option("--threads", threads, "OpenMP threads (0 = all)")->check(CLI::Range(0, 1024));
  app.add_option("--repeat", repeat, "repeats (median reported)")->check(CLI::Range(1, 100));
  CLI11_PARSE(app, argc, argv);
  if (threads > 0) omp_set_num_threads(threads);
  flush_subnormals_to_zero();  // as rupture run does (core/fp_mode.hpp)

  const Case c = bench_case(cells);
  State s = make_state(c);
  const double n = double(s.particles.size());
  fmt::print("rupture-bench: {} x {} cells, {} particles, {} steps x {} repeats, {} threads\n",
             cells, cells, s.particles.size(), steps, repeat, omp_get_max_threads());

  const char* names[] = {"sort/bin", "P2G (mass, momentum, force)", "grid update + BCs",
                         "G2P velocity + MUSL re-map", "re-mapped grid velocity",
                         "stress update + move"};
  constexpr int kPhases = 6;
  std::vector<double> rates;
  double phase_total[kPhases] = {};
  long sorts = 0;  // in the timed steps
  for (int r = 0; r < repeat; ++r) {
    double phase[kPhases] = {};
    const auto t0 = Clock::now();
    for (int k = 0; k < steps; ++k) {
      // The phases of step() for the MUSL scheme, timed one by one.
      auto t = Clock::now();
      const long sorted = s.plan.sorted_step;
      build_scatter_plan(s);
      sorts += s.plan.sorted_step != sorted ? 1 : 0;
      phase[0] += seconds_since(t), t = Clock::now();
      particles_to_grid(s, true);
      phase[1] += seconds_since(t), t = Clock::now();
      integrate_grid(s);
      phase[2] += seconds_since(t), t = Clock::now();
      update_particle_velocity_and_remap(s);
      phase[3] += seconds_since(t), t = Clock::now();
      remapped_grid_velocity(s);
      phase[4] += seconds_since(t), t = Clock::now();
      grid_to_particles(s, &GridFields::remap_x, &GridFields::remap_y, G2PMode::stress_and_move);
      phase[5] += seconds_since(t);
      s.time += s.dt;
      ++s.step;
    }
    const double wall = seconds_since(t0);
    rates.push_back(n * steps / wall);
    for (int p = 0; p < kPhases; ++p) phase_total[p] += phase[p];
  }
  fmt::print("{:<32} {:>14}\n", "phase", "ns/particle-update");
  double sum = 0;
  for (int p = 0; p < kPhases; ++p) {
    const double ns = 1e9 * phase_total[p] / (n * steps * repeat);
    sum += ns;
    fmt::print("{:<32} {:>14.2f}\n", names[p], ns);
  }
  fmt::print("{:<32} {:>14.2f}\n", "total", sum);
  std::sort(rates.begin(), rates.end());
  const double median = rates[rates.size() / 2];
  const double bytes = double(Particles::bytes_per_particle()) * n + double(s.fields.bytes());
  fmt::print("memory_bytes_per_particle={:.1f}\n", bytes / n);
  // The distance to the memory bandwidth: the model's bytes at the measured rate, against a
  // triad on 3 x 128 MiB.
  const double bytes_sort = kBytesEachSort * double(sorts) / double(steps * repeat);
  const double bytes_update = kBytesP2G + kBytesVelocity + kBytesStress + bytes_sort;
  const double achieved = bytes_update * median / 1e9;
  const double stream = stream_triad_gb_per_s(std::size_t(1) << 24, 10);
  fmt::print("model_bytes_per_particle_update={:.1f} (P2G {:.0f}, velocity {:.0f}, stress + move {:.0f}, sort {:.1f}: {} in {} steps)\n",
             bytes_update, kBytesP2G, kBytesVelocity, kBytesStress, bytes_sort, sorts, steps * repeat);
  fmt::print("achieved_bandwidth_gb_per_s={:.2f}\n", achieved);
  fmt::print("stream_triad_gb_per_s={:.2f}\n", stream);
  fmt::print("fraction_of_stream={:.2f}\n", achieved / stream);
  fmt::print("time_per_step_seconds={:.4e}\n", n / median);
  fmt::print("particle_updates_per_second={:.4e}\n", median);
  return 0;
}
