// rupture/run/outputs.hpp
// A run's periodic outputs, one object each (Output), chosen once per run (choose_outputs) and
// asked after every step, in a fixed order that the files' contents depend on, whether they are
// due: crack samples, the closing record (time.stop_at_interface_end), stations, history,
// interface profiles, Mach readings, snapshots (after a flush), the progress line, the flush
// every kFlushSeconds; the checkpoint after the step's agreement. What reads particles waits
// for a synchronized step (per-level time steps) and says by when it needs one (sync_by).
#pragma once
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "run/run_context.hpp"

namespace rupture {

struct RunIo;  // run/run_io.hpp

struct Output {
  virtual ~Output() = default;
  // The time by which the particles must be synchronized for the next write (+inf: never).
  virtual double sync_by(double /*eps*/) const { return INFINITY; }
  // Whether the step that ends at t (the run's last step when `last`) writes this output.
  virtual bool due(double t, double eps, bool last) const = 0;
  // Whether it reads the particles (then it waits for a synchronized step).
  virtual bool needs_synchronized_state() const = 0;
  // Writes, and moves the output's schedule past t.
  virtual void write(double t, double eps, bool last) = 0;
};

// At the multiples of the schedule's interval (once in a step however many it passed) and at
// the run's last step; never when the interval is 0. The history, interface profiles, Mach
// readings and snapshots; `record` writes (the schedule is a RunContext's, checkpointed).
class ScheduledOutput final : public Output {
 public:
  ScheduledOutput(Schedule& schedule, bool needs_synchronized, std::function<void()> record);
  double sync_by(double eps) const override;
  bool due(double t, double eps, bool last) const override;
  bool needs_synchronized_state() const override { return needs_synchronized_; }
  void write(double t, double eps, bool last) override;

 private:
  Schedule& schedule_;
  bool needs_synchronized_;
  std::function<void()> record_;
};

struct RunOutputs {
  std::vector<std::unique_ptr<Output>> each_step;  // in the order a step writes them
  std::unique_ptr<Output> checkpoint;              // after the step's agreement
};

// The run's outputs, for the case and context io holds (a resume: the checkpoint's schedules).
RunOutputs choose_outputs(RunIo& io);

// The time by which every level ends its step together: the next time an output needs the
// particles synchronized, at the latest the end time (minus eps).
double sync_by(const RunOutputs& outputs, double end, double eps);

// A fresh run's record at t = 0: station rows, the first energy sample, a snapshot, interface
// profiles and crack samples.
void write_first_record(RunIo& io);

}  // namespace rupture
