// rupture/cli/print_result.hpp
// What `rupture run` and `rupture resume` print when the run ends: its status, steps and times,
// the distributed split (ranks > 1), the energy balance and each interface's crack summary
// (crack.* for the first interface, crack.NAME.* for every one). The `key=value` lines are a
// public interface (scripts, sweeps and tests read them): keys, order and formats stay as they are.
#pragma once
#include <string>

#include "input/case.hpp"
#include "run/driver.hpp"

namespace rupture {

// The result of running case c into the run directory out_dir, on stdout.
void print_run_result(const Case& c, const RunResult& r, const std::string& out_dir);

}  // namespace rupture
