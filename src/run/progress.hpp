// rupture/run/progress.hpp
// Progress of a long run on stderr: step, simulated time, wall time and ETA. On a terminal
// one line is rewritten in place; otherwise a plain line is printed every `interval` seconds.
#pragma once
#include <chrono>

namespace rupture {

class Progress {
 public:
  Progress(long total_steps, double end_time, double interval_seconds, bool enabled);
  void update(long step, double time);
  void finish(long step, double time);
  double elapsed() const;

 private:
  void print(long step, double time, bool final);
  long total_steps_;
  double end_time_;
  double interval_;
  bool enabled_, tty_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace rupture
