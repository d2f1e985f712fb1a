// rupture/run/outputs.cpp
#include "run/outputs.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include "parallel/halo.hpp"
#include "run/run_io.hpp"

namespace rupture {
namespace {

// Crack samples at exact multiples of output.crack_sample_interval (E10, E11), however long the
// step, and at the end time. Distributed: the crack and rupture times and the faces come from
// their owners first (every step with time.stop_at_interface_end: the closing record reads them).
class CrackSamples final : public Output {
 public:
  explicit CrackSamples(RunIo& io) : io_(io) {}
  bool due(double t, double eps, bool last) const override {
    return io_.ctx.crack.due(t, eps) || last || io_.c.time.stop_at_interface_end;
  }
  bool needs_synchronized_state() const override { return false; }
  void write(double t, double eps, bool last) override {
    RunState& s = io_.s;
    Schedule& crack = io_.ctx.crack;
    std::vector<CrackTracker>& cracks = io_.ctx.cracks;
    collect_crack_times(s);
    while (crack.due(t, eps)) {
      for (std::size_t k = 0; k < cracks.size(); ++k) cracks[k].sample(s.interface(k), crack.next);
      crack.advance(crack.next, eps);
    }
    if (last)
      for (std::size_t k = 0; k < cracks.size(); ++k)
        if (cracks[k].samples().back().time < t - eps) cracks[k].sample(s.interface(k), t);
  }

 private:
  RunIo& io_;
};

// time.stop_at_interface_end: once a crack reached the end of its interface (before the end
// time) the record closes at this time, with a last sample of every output, and the run stops.
class ClosingRecord final : public Output {
 public:
  explicit ClosingRecord(RunIo& io) : io_(io) {}
  bool due(double, double, bool last) const override {
    if (last) return false;  // the end time closes the record anyway
    const std::vector<CrackTracker>& cracks = io_.ctx.cracks;
    return std::any_of(cracks.begin(), cracks.end(),
                       [](const CrackTracker& ct) { return ct.end_reached_time() >= 0.0; });
  }
  bool needs_synchronized_state() const override { return true; }
  void write(double t, double, bool) override {
    RunState& s = io_.s;
    RunContext& ctx = io_.ctx;
    for (std::size_t k = 0; k < ctx.cracks.size(); ++k)
      if (ctx.cracks[k].samples().back().time < t) ctx.cracks[k].sample(s.interface(k), t);
    record_energy(io_, true);
    if (ctx.prof.interval > 0) write_interfaces(io_);
    if (ctx.snapshots) ctx.snapshots->write(all_particles(s), s.stiffness(), s.time, s.step);
    if (ctx.mach_schedule.interval > 0) read_mach_angles(io_);
    io_.record.stop_reason = "crack_reached_interface_end";
    io_.closed = true;
  }

 private:
  RunIo& io_;
};

// Station rows at the multiples of output.station_interval and the last step, or every step
// without an interval. The interval paces the levels' synchronization even without stations
// (as it always has).
class StationSamples final : public Output {
 public:
  explicit StationSamples(RunIo& io)
      : io_(io), schedule_(io.ctx.station_schedule), any_(!io.c.stations.empty()) {}
  double sync_by(double eps) const override {
    if (schedule_.interval > 0) return schedule_.next - eps;
    return any_ ? -INFINITY : INFINITY;  // every step
  }
  bool due(double t, double eps, bool last) const override {
    return any_ && (schedule_.interval <= 0 || schedule_.due(t, eps) || last);
  }
  bool needs_synchronized_state() const override { return true; }
  void write(double t, double eps, bool) override {
    sample_stations_now(io_);
    schedule_.advance(t, eps);
  }

 private:
  RunIo& io_;
  Schedule& schedule_;
  bool any_;
};

// The progress line (run/progress.hpp: at most every output.progress_interval of wall time).
class ProgressLine final : public Output {
 public:
  explicit ProgressLine(RunIo& io) : io_(io) {}
  bool due(double, double, bool) const override { return true; }
  bool needs_synchronized_state() const override { return false; }
  void write(double t, double, bool) override { io_.progress.update(io_.s.step, t); }

 private:
  RunIo& io_;
};

// The record files every kFlushSeconds of wall time (a snapshot's step has flushed already; the
// last step's are written after the loop), so that a killed run keeps its record up to then.
class RecordFlush final : public Output {
 public:
  explicit RecordFlush(RunIo& io) : io_(io) {}
  bool due(double, double, bool last) const override {
    const double since = std::chrono::duration<double>(std::chrono::steady_clock::now() - io_.last_flush).count();
    return !last && io_.flushed_step != io_.s.step && since >= kFlushSeconds;
  }
  bool needs_synchronized_state() const override { return false; }
  void write(double, double, bool) override { flush_record(io_); }

 private:
  RunIo& io_;
};

// Checkpoints at the multiples of the checkpoint interval (the schedule moved on first: the
// checkpoint holds where it goes next); a stop writes one too (the driver asks for it).
class CheckpointOutput final : public Output {
 public:
  explicit CheckpointOutput(RunIo& io) : io_(io), schedule_(io.ctx.checkpoint) {}
  double sync_by(double eps) const override { return schedule_.interval > 0 ? schedule_.next - eps : INFINITY; }
  bool due(double t, double eps, bool) const override { return schedule_.due(t, eps); }
  bool needs_synchronized_state() const override { return true; }
  void write(double t, double eps, bool) override {
    schedule_.advance(t, eps);
    write_checkpoint_now(io_);
  }

 private:
  RunIo& io_;
  Schedule& schedule_;
};

}  // namespace

ScheduledOutput::ScheduledOutput(Schedule& schedule, bool needs_synchronized, std::function<void()> record)
    : schedule_(schedule), needs_synchronized_(needs_synchronized), record_(std::move(record)) {}

double ScheduledOutput::sync_by(double eps) const {
  // Only what reads the particles asks the levels to end their steps together.
  return needs_synchronized_ && schedule_.interval > 0 ? schedule_.next - eps : INFINITY;
}

bool ScheduledOutput::due(double t, double eps, bool last) const {
  return schedule_.due(t, eps) || (last && schedule_.interval > 0);
}

void ScheduledOutput::write(double t, double eps, bool) {
  record_();
  schedule_.advance(t, eps);
}

RunOutputs choose_outputs(RunIo& io) {
  RunContext& ctx = io.ctx;
  RunOutputs out;
  auto add = [&](std::unique_ptr<Output> o) { out.each_step.push_back(std::move(o)); };
  add(std::make_unique<CrackSamples>(io));
  if (io.c.time.stop_at_interface_end) add(std::make_unique<ClosingRecord>(io));
  add(std::make_unique<StationSamples>(io));
  add(std::make_unique<ScheduledOutput>(ctx.hist, true, [&io] { record_energy(io, true); }));
  if (ctx.prof.interval > 0)  // profiles read the interfaces only
    add(std::make_unique<ScheduledOutput>(ctx.prof, false, [&io] { write_interfaces(io); }));
  if (ctx.mach_schedule.interval > 0)
    add(std::make_unique<ScheduledOutput>(ctx.mach_schedule, true, [&io] { read_mach_angles(io); }));
  if (ctx.snapshots)
    add(std::make_unique<ScheduledOutput>(ctx.snap, true, [&io] {
      RunState& s = io.s;
      flush_record(io);  // the small record files first: they say what happened if the disk fills
      io.ctx.snapshots->write(all_particles(s), s.stiffness(), s.time, s.step);
    }));
  if (ctx.tip_schedule.interval > 0)  // J and K read the particles near the tips
    add(std::make_unique<ScheduledOutput>(ctx.tip_schedule, true, [&io] {
      sample_stress_intensity(io.c, io.s, io.ctx.cracks, io.ctx.growth, io.ctx.tips);
    }));
  add(std::make_unique<ProgressLine>(io));
  add(std::make_unique<RecordFlush>(io));
  out.checkpoint = std::make_unique<CheckpointOutput>(io);
  return out;
}

double sync_by(const RunOutputs& outputs, double end, double eps) {
  double by = end - eps;
  for (const std::unique_ptr<Output>& o : outputs.each_step) by = std::min(by, o->sync_by(eps));
  if (outputs.checkpoint) by = std::min(by, outputs.checkpoint->sync_by(eps));
  return by;
}

void write_first_record(RunIo& io) {
  RunState& s = io.s;
  RunContext& ctx = io.ctx;
  if (!io.c.stations.empty()) sample_stations_now(io);
  record_energy(io, false);
  if (ctx.snapshots) ctx.snapshots->write(all_particles(s), s.stiffness(), s.time, s.step);
  if (io.c.output.interface_interval > 0) write_interfaces(io);
  for (std::size_t k = 0; k < ctx.cracks.size(); ++k) ctx.cracks[k].sample(s.interface(k), s.time);
}

}  // namespace rupture
