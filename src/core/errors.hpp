// rupture/core/errors.hpp
// The two ways a run can fail, kept apart because users act on them differently:
// InputError  - the case file (or a --set override) is wrong; raised before any work starts,
//               the message names the key, the value and what is allowed.
// SimulationError - the run became unphysical (NaN, particle off the grid, energy blow-up);
//               the message says what, where and when.
// IoError     - a file could not be written or read (full disk, permissions); the message names
//               the file and the operating system's reason (strerror).
#pragma once
#include <stdexcept>
#include <string>

namespace rupture {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SimulationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct IoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace rupture
