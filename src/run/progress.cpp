// rupture/run/progress.cpp
#include "run/progress.hpp"

#include <cstdio>
#include <fmt/format.h>
#include <unistd.h>

namespace rupture {

Progress::Progress(long total_steps, double end_time, double interval_seconds, bool enabled)
    : total_steps_(total_steps),
      end_time_(end_time),
      interval_(interval_seconds),
      enabled_(enabled),
      tty_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(long step, double time) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_).count();
  if (since < (tty_ ? 0.2 : interval_)) return;
  last_ = now;
  print(step, time, false);
}

void Progress::finish(long step, double time) {
  if (enabled_) print(step, time, true);
}

void Progress::print(long step, double time, bool final) {
  const double wall = elapsed();
  const double frac = end_time_ > 0 ? time / end_time_ : 1.0;
  const double eta = frac > 0 ? wall * (1.0 - frac) / frac : 0.0;
  // Microseconds for laboratory runs, seconds for those that last a millisecond or more.
  const bool micro = end_time_ < 1e-3;
  const std::string line =
      fmt::format("step {}/{}  t = {:.4g} {} ({:5.1f} %)  wall {:.1f} s  ETA {:.1f} s", step,
                  total_steps_, micro ? time * 1e6 : time, micro ? "us" : "s", 100.0 * frac,
                  wall, eta);
  if (tty_) {
    fmt::print(stderr, "\r{:<90}{}", line, final ? "\n" : "");
  } else {
    fmt::print(stderr, "{}\n", line);
  }
  std::fflush(stderr);
}

}  // namespace rupture
