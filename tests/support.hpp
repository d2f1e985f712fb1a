// Shared helpers for tests: a small valid case as TOML text, with hooks to modify it.
#pragma once
#include <string>

namespace rupture::test {

// Homalite-100 (SPEC §1) as a [materials] table, shared by the test cases.
inline constexpr const char* kHomaliteToml = R"(
[materials.homalite]
youngs_modulus = 5.2e9
poisson_ratio = 0.34
density = 1246.0
)";

// A valid single-body Homalite strip. Lines can be replaced by tests of bad input.
inline std::string strip_case_toml() {
  return R"(
title = "test strip"
[model]
plane = "strain"
[materials.homalite]
youngs_modulus = 5.2e9
poisson_ratio = 0.34
density = 1246.0
[grid]
min = [0.0, 0.0]
max = [0.01, 0.002]
cell_size = 0.5e-3
particles_per_cell = 2
[bodies.strip]
material = "homalite"
min = [0.0, 0.0]
max = [0.01, 0.002]
[time]
end = 2e-6
cfl = 0.4
[solver]
scheme = "MUSL"
flip = 1.0
[boundary.push]
edge = "left"
component = "x"
function = "constant"
velocity = 1.0
[output]
history_interval = 0.1e-6
)";
}

}  // namespace rupture::test
