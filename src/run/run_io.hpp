// rupture/run/run_io.hpp
// RunIo: what a run's outputs read (the case, the context, the stations' probes, the speeds
// the crack files report against) and keep from step to step (run.json's record, progress,
// the last flush), with the writes they share. Rank 0 alone writes the run directory:
// distributed, a write failing there waits in pending_write for the step's agreement, which
// stops every rank with it (nothing rank 0 alone writes is tried after it); one process throws.
#pragma once
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "input/case.hpp"
#include "output/run_json.hpp"
#include "output/stations.hpp"
#include "material/elastic.hpp"
#include "run/driver.hpp"
#include "run/progress.hpp"
#include "run/run_context.hpp"
#include "solver/summary.hpp"

namespace rupture {

struct RunIo {
  // Collective: the run's particles are counted over the ranks.
  RunIo(const Case& c, const CaseSummary& summary, const RunOptions& options, RunContext& ctx,
        std::vector<StationProbe> probes);

  const Case& c;
  const CaseSummary& summary;
  const RunOptions& options;
  const std::string dir;  // the run directory
  const Comm& comm;
  const bool writer;      // rank 0: writes the run directory
  RunContext& ctx;
  RunState& s;            // ctx.s
  std::vector<StationProbe> probes;     // per [stations] entry
  std::vector<WaveSpeeds> crack_speeds;  // per interface: its lower body's material's
  std::vector<double> shear_speed;       // per material, m/s (Mach readings)
  const long total_particles;            // over the ranks
  RunRecord record;                      // run.json
  Progress progress;                     // the progress line and the wall clock of this segment
  double peak_work = 0.0;                // check_energy: the most the loads' work has been, J/m
  std::string pending_write;             // rank 0's failed write (distributed), until agreed on
  std::chrono::steady_clock::time_point last_flush = std::chrono::steady_clock::now();
  long flushed_step = -1;  // the step whose end the record files were last brought up to date at
  bool closed = false;     // the record closed before the end time: the run stops after this step
};

// run.json's heartbeat: now, as Unix seconds and as UTC text.
void stamp_heartbeat(RunRecord& r);

// The record a run starts with (run.json "running": threads, ranks, segment, identity, input
// hash, the checkpoint a resume starts from) written with units.csv by rank 0.
void open_record(RunIo& io);

// Before the first step (after a fresh run's record at t = 0): the wall clock and progress line
// start, and the energy check's peak work is the history's so far.
void begin_steps(RunIo& io);

// Runs `write` on rank 0 only; distributed, a failure is kept in io.pending_write (and nothing
// is written after it), one process lets it through.
void writer_only(RunIo& io, const std::function<void()>& write);

// The outputs' writes: the interface profiles (interface/*.csv, the next file number); the
// Mach-angle readings (theory E12) behind each crack (collective); the crack files; station rows
// (collective); an energy sample appended to the history and checked (collective).
void write_interfaces(RunIo& io);
void read_mach_angles(RunIo& io);
void write_cracks(RunIo& io);
void sample_stations_now(RunIo& io);
void record_energy(RunIo& io, bool check);

// run.json's record brought up to the state now: steps, times, energies, heartbeat.
void fill_record(RunIo& io);

// The record files (history.csv, the crack files, stations, run.json "running") brought up to
// date; a failure as writer_only says.
void flush_record(RunIo& io);

// A checkpoint of the context now (a part file per rank when distributed), holding the wall
// time so far; run.json records its time and step.
void write_checkpoint_now(RunIo& io);

// The small record files: history.csv, the crack files and the stations' (run by rank 0).
void write_record_files(RunIo& io);

}  // namespace rupture
