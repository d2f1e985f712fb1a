// rupture/run/run_setup.hpp
// A run's start, before its first step: rank 0 prepares the run directory (every rank learns
// whether it could), the context is set up from the case (state, crack trackers, snapshot
// writer, output schedules) and, on resume, replaced by the checkpoint and split over the
// ranks. What one rank cannot do stops every rank with its message; a new run's run.json then
// says how it ended (a resume leaves the directory as its last segment left it).
#pragma once
#include <string>
#include <vector>

#include "input/case.hpp"
#include "output/stations.hpp"
#include "run/driver.hpp"
#include "run/run_context.hpp"
#include "solver/summary.hpp"

namespace rupture {

// A fresh run: the directory made (an existing run's files deleted with RunOptions::overwrite);
// a resume: made if missing. InputError on every rank when rank 0 could not.
void prepare_dir(const std::string& dir, const RunOptions& o);

// Sets up ctx for the case, fresh or from the output directory's checkpoint (RunOptions::
// resume), and returns where the stations read (from the state at t = 0: a body station
// follows the particle nearest its point then, whatever the checkpoint holds).
std::vector<StationProbe> start_run(RunContext& ctx, const Case& c, const CaseSummary& summary,
                                    const RunOptions& options);

}  // namespace rupture
