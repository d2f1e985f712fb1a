// rupture/run/run_io.cpp
#include "run/run_io.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fmt/format.h>

#include "cohesive/crack_tip.hpp"
#include "cohesive/mach_angle.hpp"
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/fault_injection.hpp"
#include "output/crack_xdmf.hpp"
#include "output/csv_units.hpp"
#include "output/interface_csv.hpp"
#include "parallel/halo.hpp"
#include "run/checkpoint.hpp"
#include "run/checkpoint_ranks.hpp"
#include "run/energy_check.hpp"

namespace rupture {
namespace {

// FNV-1a of the case text and its overrides, in hex: which input a run started from.
std::string case_hash(const CaseSource& source) {
  std::uint64_t h = 1469598103934665603ull;
  auto add = [&](const std::string& text) {
    for (const unsigned char ch : text) h = (h ^ ch) * 1099511628211ull;
    h = (h ^ 0xffu) * 1099511628211ull;  // a separator no text byte can fake alone
  };
  add(source.text);
  for (const std::string& o : source.overrides) add(o);
  return fmt::format("{:016x}", h);
}

// Crack speeds are reported against the speeds of the lower body's material.
std::vector<WaveSpeeds> lower_body_speeds(const Case& c, const CaseSummary& summary) {
  std::vector<WaveSpeeds> speeds;  // per interface
  for (const InterfaceSpec& is : c.interfaces)
    speeds.push_back(summary.speeds[std::size_t(c.bodies[is.lower_body].material)]);
  return speeds;
}

std::vector<double> shear_speeds(const CaseSummary& summary) {
  std::vector<double> shear;  // per material
  for (const WaveSpeeds& w : summary.speeds) shear.push_back(w.shear);
  return shear;
}

Progress make_progress(const RunIo& io) {
  return Progress(io.summary.steps, io.c.time.end, io.c.output.progress_interval,
                  io.options.progress && io.writer);
}

}  // namespace

RunIo::RunIo(const Case& c_, const CaseSummary& summary_, const RunOptions& options_, RunContext& ctx_,
             std::vector<StationProbe> probes_)
    : c(c_),
      summary(summary_),
      options(options_),
      dir(options_.output_dir),
      comm(options_.comm),
      writer(options_.comm.rank() == 0),
      ctx(ctx_),
      s(ctx_.s),
      probes(std::move(probes_)),
      crack_speeds(lower_body_speeds(c_, summary_)),
      shear_speed(shear_speeds(summary_)),
      total_particles(sum_over_ranks(ctx_.s, long(held_particles(ctx_.s)))),
      progress(make_progress(*this)) {}

void stamp_heartbeat(RunRecord& r) {
  const auto now = std::chrono::system_clock::now();
  r.heartbeat_unix = std::chrono::duration<double>(now.time_since_epoch()).count();
  const std::time_t t = std::chrono::system_clock::to_time_t(now);
  std::tm utc{};
  gmtime_r(&t, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  r.heartbeat = buf;
}

void open_record(RunIo& io) {
  RunRecord& record = io.record;
  record.threads = omp_get_max_threads();
  record.ranks = io.comm.size();
  record.segments = io.ctx.segments;
  record.run_id = io.ctx.run_id;
  record.case_hash = case_hash(io.options.source);
  if (io.options.resume) record.checkpoint_time = io.s.time, record.checkpoint_step = io.s.step;
  stamp_heartbeat(record);
  if (io.writer) {
    write_file_atomic(io.dir + "/run.json", run_json(io.c, io.summary, record));
    write_csv_units(io.dir);  // what every CSV column holds, in which unit
  }
}

void begin_steps(RunIo& io) {
  // A resume: the most the loads' work has been so far.
  for (const EnergySample& e : io.ctx.history.samples)
    io.peak_work = std::max(io.peak_work, std::fabs(e.external_work));
  io.progress = make_progress(io);  // the wall time counts the steps and their outputs
}

void writer_only(RunIo& io, const std::function<void()>& write) {
  if (!io.writer) return;
  if (!io.comm.distributed()) return write();
  if (!io.pending_write.empty()) return;
  try {
    write();
  } catch (const std::exception& e) {
    io.pending_write = e.what();
  }
}

void write_interfaces(RunIo& io) {
  namespace fs = std::filesystem;
  RunState& s = io.s;
  if (s.num_interfaces() == 0) return;
  collect_interface_state(s);  // distributed: every node from its owner
  writer_only(io, [&] {
    const std::string& dir = io.dir;
    const std::vector<std::string>& names = io.c.interface_names;
    const int number = io.ctx.interface_files;
    fs::create_directories(dir + "/interface");
    for (std::size_t k = 0; k < s.num_interfaces(); ++k) {
      // Branches split off growing cracks (solver/crack_branching.hpp) come after the case's
      // interfaces: branch1, branch2, ... in the order they split off.
      const std::string name = k < names.size() ? names[k] : fmt::format("branch{}", k - names.size() + 1);
      const std::string named = fmt::format("{}/interface/{}_{:06d}.csv", dir, name, number);
      if (k > 0 || names[0] == "interface") {
        write_interface_csv(named, s.interface(k), s.time);
        continue;
      }
      // The first interface keeps its original name, interface_NNNNNN.csv; the file named after
      // it is a hard link to the same data (a copy where links are not possible).
      const std::string first = fmt::format("{}/interface/interface_{:06d}.csv", dir, number);
      write_interface_csv(first, s.interface(0), s.time);
      std::error_code ec;
      fs::remove(named, ec);
      fs::create_hard_link(first, named, ec);
      if (ec) fs::copy_file(first, named, fs::copy_options::overwrite_existing);
    }
    ++io.ctx.interface_files;
  });
}

void read_mach_angles(RunIo& io) {
  // theory E12 (output.mach_interval): the shear Mach front behind each crack running above c_S.
  // Distributed: each rank bins its particles, the bins summed over the ranks (collective).
  const Comm& comm = io.comm;
  const SumOverRanks sum_bins = [&comm](double* v, int n) { comm.sum(v, n); };
  RunState& s = io.s;
  const Particles& particles = all_particles(s);
  for (std::size_t k = 0; k < io.ctx.cracks.size(); ++k) {
    MachReading m;
    if (read_mach_angle(io.ctx.cracks[k], io.crack_speeds[k].shear, particles, s.run_grid(), io.shear_speed, s.time,
                        m, comm.distributed() ? &sum_bins : nullptr)) {
      m.interface = int(k);
      io.ctx.mach.push_back(m);
    }
  }
}

void write_cracks(RunIo& io) {
  // The first interface keeps the original names (crack_tip.csv); every interface also gets
  // files named after it.
  const std::string& dir = io.dir;
  std::vector<CrackTracker>& cracks = io.ctx.cracks;
  const std::vector<WaveSpeeds>& speeds = io.crack_speeds;
  for (std::size_t k = 0; k < cracks.size(); ++k) {
    const std::string suffix = "_" + io.c.interface_names[k];
    if (k == 0) cracks[0].write(dir, "", speeds[0].rayleigh, speeds[0].shear);
    cracks[k].write(dir, suffix, speeds[k].rayleigh, speeds[k].shear);
    write_rupture_times(dir, suffix, io.s.interface(k));
    if (io.c.output.mach_interval > 0) {
      if (k == 0) write_mach_angles(dir, "", io.ctx.mach, 0);
      write_mach_angles(dir, suffix, io.ctx.mach, int(k));
    }
  }
}

void sample_stations_now(RunIo& io) {
  sample_stations(io.s, io.probes, io.ctx.stations);
}

void record_energy(RunIo& io, bool check) {
  std::vector<EnergySample>& samples = io.ctx.history.samples;
  samples.push_back(sample_energy(io.s));
  if (check) check_energy(io.s, samples.back(), io.peak_work);
}

void fill_record(RunIo& io) {
  RunRecord& r = io.record;
  const RunState& s = io.s;
  const History& history = io.ctx.history;
  const EnergySample& e = history.samples.back();
  r.steps = s.step;
  r.simulated_time = s.time;
  r.wall_seconds = io.ctx.wall_before + io.progress.elapsed();
  r.particle_updates_per_second =
      r.wall_seconds > 0 ? double(io.total_particles) * double(s.step) / r.wall_seconds : 0.0;
  r.cohesive_seconds = s.cohesive_seconds;
  r.growth_seconds = io.ctx.growth_seconds;
  r.kinetic_energy = e.kinetic;
  r.strain_energy = e.strain;
  r.external_work = e.external_work;
  // After the start-up: 1 us in the laboratory, 5 % of the run when that is longer.
  r.energy_balance_error = history.max_relative_error(std::max(1e-6, 0.05 * io.c.time.end));
  r.energy_balance_error_final = e.relative_error();
  r.min_cohesive_dt = s.limits.min_cohesive_dt;
  r.cohesive_stored = e.cohesive_stored;
  r.cohesive_dissipated = e.cohesive_dissipated;
  r.faces.resize(io.c.interfaces.size());
  for (std::size_t k = 0; k < r.faces.size(); ++k)
    r.faces[k] = {s.interface(k).spec.upper_faces, s.interface(k).spec.lower_faces};
  stamp_heartbeat(r);
}

void flush_record(RunIo& io) {
  io.flushed_step = io.s.step;
  writer_only(io, [&] {
    if (fault_due(FaultSite::record_write, io.s.step))  // tests
      throw IoError(fmt::format("error while writing '{}/history.csv': No space left on device "
                                "(injected: RUPTURE_INJECT_FAULT)", io.dir));
    write_record_files(io);
    fill_record(io);
    write_file_atomic(io.dir + "/run.json", run_json(io.c, io.summary, io.record));
    io.last_flush = std::chrono::steady_clock::now();
  });
}

void write_checkpoint_now(RunIo& io) {
  RunContext& ctx = io.ctx;
  const double wall_before = ctx.wall_before;
  ctx.wall_before += io.progress.elapsed();  // the checkpoint holds the wall time up to here
  if (io.comm.distributed())
    write_checkpoint_ranks(io.dir, io.options.source, ctx, io.comm);  // particle parts per rank
  else
    write_checkpoint(io.dir, io.options.source, ctx);
  ctx.wall_before = wall_before;
  io.record.checkpoint_time = io.s.time;
  io.record.checkpoint_step = io.s.step;
}

void write_record_files(RunIo& io) {
  io.ctx.history.write(io.dir + "/history.csv");
  write_cracks(io);
  write_stations(io.dir, io.c.stations, io.probes, io.ctx.stations);
  write_stress_intensity(io.dir, io.c, io.ctx.tips);
  write_crack_paths(io.dir, io.c, io.ctx.growth);
  if (io.ctx.snapshots && io.comm.rank() == 0) write_cracks_xdmf(io.dir, io.c, io.ctx.growth, io.ctx.snapshots->times());
}

}  // namespace rupture
