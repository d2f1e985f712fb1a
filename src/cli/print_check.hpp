// rupture/cli/print_check.hpp
// What `rupture check` prints (and `rupture run` before it starts): the case's derived
// quantities (print_check), the split among N processes (print_rank_plan, --ranks N) and the
// wall time predicted from a few timed steps (print_predicted_time). The `key=value` lines are
// a public interface (scripts and tests read them): keys, order and formats stay as they are.
#pragma once
#include <string>

#include "input/case.hpp"

namespace rupture {

// The case at `path`: materials' wave speeds, bodies, time step limits, interfaces, grid and
// particle counts, steps and the memory estimate.
void print_check(const std::string& path, const Case& c);

// rupture check --ranks N: how a distributed run would split the case (parallel/rank_plan.hpp).
void print_rank_plan(const Case& c, int ranks);

// The run's wall time predicted from a few timed steps of this case on this machine
// (run/step_cost.hpp); the progress line's ETA refines it during the run.
void print_predicted_time(const Case& c);

}  // namespace rupture
