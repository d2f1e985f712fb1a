// rupture/run/run_result.hpp
// How a run ended, put together after its last step: the outcome (completed, interrupted,
// unstable, io_error) in the RunResult and in run.json's record, the record files written a
// last time by rank 0 (after a failed write too: the small files may still fit), the run's
// sums over the ranks (particles, exchanges, peak memory), each interface's crack summary, and
// run.json. Every rank calls these together (collective).
#pragma once
#include <string>

#include "run/driver.hpp"
#include "run/run_io.hpp"

namespace rupture {

// Why the time loop ended, besides io.record.stop_reason.
struct RunEnd {
  int signal = 0;           // the signal that interrupted the run (0: none or a test's stop)
  std::string unstable;     // the diagnosis of a run that went unstable (SimulationError)
  std::string io_failure;   // what failed to be written (IoError, filesystem_error)
};

// The result's first part, known before the first step: the ranks and their particles.
RunResult starting_result(const RunState& s, const Comm& comm);

// The result of the run in io, given how its loop ended; its first step was first_step (0, or
// a resume's). Writes the last record files and run.json.
RunResult finish_run(RunIo& io, RunResult result, const RunEnd& end, long first_step);

}  // namespace rupture
