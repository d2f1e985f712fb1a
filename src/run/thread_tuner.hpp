// rupture/run/thread_tuner.hpp
// The run's OpenMP thread count, chosen from its measured step times when the case leaves
// solver.threads at 0 (all cores). Threads pay only when each has a core: beside another busy
// process (a second run, `rupture sweep -j`, a build) the threads of libgomp spin at every
// barrier on a core the other work holds, and 2 threads ran at 0.68 of 1 thread's speed
// (docs/performance.md, "Threads on a busy machine"). So the run times a window of steps on all
// threads; where the threads had their cores (the process's CPU time is at least kOwnCores of
// threads x wall time: libgomp's threads spin, so an idle machine gives them all of it) it keeps
// them at no cost; otherwise it times a window on 1 thread and keeps the faster. Then it runs a
// period on that count and measures again, with periods that double while the choice holds
// (load comes and goes). Results do not depend on the thread
// count (every sum over particles or segments is taken in a fixed order), so the choice changes
// no answer, only the time.
// The decision is a plain state machine over step times (testable without threads or a clock);
// the driver calls it after each step with that step's wall seconds and sets the count it gives.
#pragma once
#include <vector>

namespace rupture {

class ThreadTuner {
 public:
  // Steps per probe window: the first (after the change of count) is not counted, then 16, whose
  // mean is compared: with per-level time steps the cost of a step follows the levels' cycle
  // (a coarse level steps once in 2, 4, ... finest steps), and 16 consecutive steps hold whole
  // cycles of up to 16 finest steps, so the two windows weigh the same work.
  static constexpr int kWindow = 17;
  static constexpr long kFirstPeriod = 300;  // steps on the chosen count before measuring again
  static constexpr long kLongestPeriod = 2400;
  static constexpr double kMargin = 0.02;    // 1 thread must be this much faster to be chosen
  static constexpr double kOwnCores = 0.9;   // CPU / (threads x wall) above this: no contention

  // many: the threads the machine gives (omp_get_max_threads() at the start); inactive (always
  // `many`) when many <= 1 or the case fixed solver.threads.
  ThreadTuner(int many, bool active);
  // The thread count for the next step, after a step that took `seconds` (wall) and `cpu`
  // seconds of the process's CPU time (all its threads).
  int after_step(double seconds, double cpu);
  int threads() const { return threads_; }
  bool probing() const { return phase_ != Phase::run; }
  // Windows measured so far, and how many chose 1 thread (for the run record).
  int decisions() const { return decisions_; }
  int chose_one() const { return chose_one_; }

 private:
  enum class Phase { probe_many, probe_one, run };
  static double mean(const std::vector<double>& v);
  void decide(int choice);

  int many_;
  bool active_;
  int threads_;
  Phase phase_ = Phase::probe_many;
  std::vector<double> times_many_, times_one_;
  double cpu_many_ = 0.0;
  int window_steps_ = 0;
  long run_left_ = 0;
  long period_ = kFirstPeriod;
  int last_choice_ = 0;
  int decisions_ = 0, chose_one_ = 0;
};

}  // namespace rupture
