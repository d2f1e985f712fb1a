// Shared helpers for tests: small valid cases as TOML text (a strip; two bodies with an interface),
// with hooks to modify them.
#pragma once
#include <gtest/gtest.h>

#include <string>

namespace rupture::test {

// Homalite-100 (theory §1) as a [materials] table, shared by the test cases.
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

// Two bodies of their own fields, upper [0, 8] x [0, 4] mm over lower [0, 8] x [-4, 0] mm,
// with [interface.w] holding `lines`.
inline std::string case_with(const std::string& lines) {
  return std::string(R"(
title = "interface parsing"
[model]
plane = "strain"
)") + test::kHomaliteToml +
         R"(
[grid]
min = [0.0, -0.004]
max = [0.008, 0.004]
cell_size = 1e-3
[bodies.upper]
material = "homalite"
min = [0.0, 0.0]
max = [0.008, 0.004]
[bodies.lower]
material = "homalite"
min = [0.0, -0.004]
max = [0.008, 0.0]
[interface.w]
)" + lines + R"(
[time]
end = 1e-6
)";
}

// The upper body over the lower one along y = 0, x in [2, 6] mm (case_with's [interface.w]).
inline const std::string kGeometry = "upper_body = \"upper\"\nlower_body = \"lower\"\ny = 0.0\nstart = 0.002\nend = 0.006\nsegments = 3\n";

// `text` with its first `from` replaced (the test's own setup must hold `from`).
inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test setup: '" << from << "' not in the lines";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace rupture::test
