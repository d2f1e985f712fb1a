// rupture/cli/print_result.cpp
#include "cli/print_result.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <utility>

#include "cohesive/crack_tip.hpp"
#include "material/elastic.hpp"

namespace rupture {
namespace {

// Units that fit the case's scale, for the lines people read (the key=value lines stay SI):
// lengths from the domain's size, times from a shear wave's crossing of it (python/rupture/
// plot.py Scale chooses the same), km/s where lengths are km.
struct ReadableUnits {
  double lf = 1.0, tf = 1.0, vf = 1.0;
  const char *l = "m", *t = "s", *v = "m/s";
};

ReadableUnits readable_units(const Case& c) {
  ReadableUnits u;
  const double size = std::max(c.grid.max[0] - c.grid.min[0], c.grid.max[1] - c.grid.min[1]);
  double c_s = INFINITY;
  for (const ElasticMaterial& m : c.materials) c_s = std::min(c_s, wave_speeds(m, c.plane).shear);
  const double crossing = size / c_s;
  if (size >= 1e3) u.lf = 1e-3, u.l = "km", u.vf = 1e-3, u.v = "km/s";
  else if (size < 1.0) u.lf = 1e3, u.l = "mm";
  if (crossing < 1e-3) u.tf = 1e6, u.t = "us";
  else if (crossing < 0.1) u.tf = 1e3, u.t = "ms";
  return u;
}

// One line per interface in those units, after the key=value lines ("# ...": no key).
void print_readable_summary(const Case& c, const RunResult& r) {
  const ReadableUnits u = readable_units(c);
  for (std::size_t i = 0; i < r.cracks.size(); ++i) {
    const CrackSummary& q = r.cracks[i];
    const InterfaceSpec& is = c.interfaces[i];
    const ElasticMaterial& lower = c.materials[std::size_t(c.bodies[std::size_t(is.lower_body)].material)];
    const WaveSpeeds w = wave_speeds(lower, c.plane);
    std::string line = fmt::format("# {} {}: ", q.fault ? "fault" : "crack", c.interface_names[i]);
    if (q.grows) {
      // A crack that nucleates says when first (solver/crack_nucleation.hpp).
      const std::string born = q.nucleates ? fmt::format("nucleated at {:.4g} {}", u.tf * q.nucleation_time, u.t) : "";
      if (q.nucleates && q.nucleation_time < 0.0) fmt::print("{}did not nucleate\n", line);
      else if (q.grown_length == 0.0) fmt::print("{}{}did not grow\n", line, q.nucleates ? born + " and " : "");
      else
        fmt::print("{}{}grew from {:.4g} {} at {:.2f} degrees to its direction, by {:.4g} {} ({} branches)\n", line,
                   q.nucleates ? born + ", " : "", u.tf * q.initiation_time, u.t, q.initial_angle,
                   u.lf * q.grown_length, u.l, q.branches);
      continue;
    }
    if (!q.initiated && !(q.fault && q.front.ruptured)) {
      fmt::print("{}did not initiate\n", line);
      continue;
    }
    if (q.fault) {
      const FrontSummary& f = q.front;
      line += fmt::format("nucleated at {:.4g} {} on s in [{:.4g}, {:.4g}] {}", u.tf * f.nucleation_time, u.t,
                          u.lf * f.nucleation_begin_s, u.lf * f.nucleation_end_s, u.l);
      for (const auto& [side, fs] : {std::pair{"forward", &f.forward}, std::pair{"backward", &f.backward}}) {
        if (fs->nodes == 0) continue;
        line += fmt::format("; {} {:.4g} {} ({:.2f} c_S {}, {}) to s {:.4g} {}", side, u.vf * fs->speed, u.v,
                            fs->speed / w.shear, lower.name, fs->regime, u.lf * fs->reach_s, u.l);
        if (fs->supershear_s >= 0.0)
          line += fmt::format(", supershear from s {:.4g} {} at {:.4g} {}", u.lf * fs->supershear_s, u.l,
                              u.tf * fs->supershear_time, u.t);
      }
    } else {
      line += fmt::format("initiated at {:.4g} {} at s {:.4g} {}; sustained {:.4g} {} ({:.2f} c_R {}, {})",
                          u.tf * q.initiation_time, u.t, u.lf * q.initiation_s, u.l, u.vf * q.sustained_speed,
                          u.v, q.sustained_speed / w.rayleigh, lower.name, q.regime);
      if (q.arrested) line += fmt::format("; arrested at s {:.4g} {}", u.lf * q.arrest_s, u.l);
    }
    fmt::print("{}\n", line);
  }
}

}  // namespace

void print_run_result(const Case& c, const RunResult& r, const std::string& out_dir) {
  fmt::print("status={}\n", r.status);
  fmt::print("stop_reason={}\n", r.stop_reason);
  fmt::print("steps={}\n", r.steps);
  fmt::print("simulated_time={:.6e}\n", r.simulated_time);
  fmt::print("wall_seconds={:.3f}\n", r.wall_seconds);
  fmt::print("particle_updates_per_second={:.4e}\n", r.particle_updates_per_second);
  fmt::print("cohesive_seconds={:.3f}\n", r.cohesive_seconds);
  if (std::any_of(c.interfaces.begin(), c.interfaces.end(), [](const InterfaceSpec& i) { return i.growth.on(); }))
    fmt::print("growth_seconds={:.3f}\n", r.growth_seconds);
  if (r.ranks > 1) {  // distributed: how the particles were split, and how often they moved
    fmt::print("ranks={}\n", r.ranks);
    fmt::print("particles_per_rank={}\n", fmt::join(r.particles_per_rank, ","));
    fmt::print("particles_per_rank_end={}\n", fmt::join(r.particles_per_rank_end, ","));
    fmt::print("migrations={}\n", r.migrations);
    fmt::print("rebalances={}\n", r.rebalances);
    fmt::print("reach_widenings={}\n", r.reach_widenings);
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
    // theory E12: the shear Mach angle read at the snapshot times (-1: not measured).
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
      if (q.grows) {  // a crack that grows off its line (initiation_time above: its first step)
        fmt::print("crack.{}.initial_angle={:.2f}\n", n, q.initial_angle);
        fmt::print("crack.{}.branches={}\n", n, q.branches);
        fmt::print("crack.{}.length={:.6e}\n", n, q.grown_length);
        if (q.nucleates) fmt::print("crack.{}.nucleation_time={:.6e}\n", n, q.nucleation_time);
      }
      if (q.fault) {  // the rupture front outside the nucleation patch (cohesive/rupture_front.hpp)
        const FrontSummary& f = q.front;
        fmt::print("crack.{}.nucleation_time={:.6e}\n", n, f.nucleation_time);
        fmt::print("crack.{}.front_speed={:.1f}\n", n, f.speed);
        fmt::print("crack.{}.front_peak_speed={:.1f}\n", n, f.peak_speed);
        fmt::print("crack.{}.front_regime={}\n", n, f.regime);
        for (const auto& [side, fs] : {std::pair{"forward", &f.forward}, std::pair{"backward", &f.backward}}) {
          fmt::print("crack.{}.front_{}_speed={:.1f}\n", n, side, fs->speed);
          fmt::print("crack.{}.front_{}_reach_s={:.6e}\n", n, side, fs->reach_s);
          fmt::print("crack.{}.front_{}_supershear_s={:.6e}\n", n, side, fs->supershear_s);
        }
      }
    }
  }
  print_readable_summary(c, r);
  fmt::print("output={}\n", out_dir);
}

}  // namespace rupture
