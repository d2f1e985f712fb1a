// rupture/run/thread_tuner.cpp
#include "run/thread_tuner.hpp"

#include <algorithm>

namespace rupture {

ThreadTuner::ThreadTuner(int many, bool active)
    : many_(many), active_(active && many > 1), threads_(many) {
  if (!active_) phase_ = Phase::run;
}

double ThreadTuner::mean(const std::vector<double>& v) {
  double sum = 0.0;
  for (const double x : v) sum += x;
  return v.empty() ? 0.0 : sum / double(v.size());
}

// The means of the two windows (the step's own time: the driver leaves the outputs out); all
// the threads unless 1 is faster by the margin. A period doubles while the choice holds
// and starts again from the first when it changes.
void ThreadTuner::decide(int choice) {
  const bool one = choice == 1;
  ++decisions_;
  chose_one_ += one ? 1 : 0;
  period_ = choice == last_choice_ ? std::min(2 * period_, kLongestPeriod) : kFirstPeriod;
  last_choice_ = choice;
  threads_ = choice;
  run_left_ = period_;
  phase_ = Phase::run;
}

int ThreadTuner::after_step(double seconds, double cpu) {
  if (!active_) return threads_;
  switch (phase_) {
    case Phase::probe_many:
    case Phase::probe_one: {
      // The window's first step follows a change of count (threads waking, caches): not counted.
      if (window_steps_ > 0) {
        (phase_ == Phase::probe_many ? times_many_ : times_one_).push_back(seconds);
        if (phase_ == Phase::probe_many) cpu_many_ += cpu;
      }
      if (++window_steps_ < kWindow) break;
      window_steps_ = 0;
      if (phase_ == Phase::probe_one) {
        decide(mean(times_one_) < (1.0 - kMargin) * mean(times_many_) ? 1 : many_);
      } else if (cpu_many_ >= kOwnCores * many_ * mean(times_many_) * double(times_many_.size())) {
        decide(many_);  // every thread had its core: nothing to gain on fewer
      } else {
        phase_ = Phase::probe_one;
        threads_ = 1;
      }
      break;
    }
    case Phase::run:
      if (--run_left_ > 0) break;
      times_many_.clear(), times_one_.clear();
      cpu_many_ = 0.0;
      phase_ = Phase::probe_many;
      threads_ = many_;
      break;
  }
  return threads_;
}

}  // namespace rupture
