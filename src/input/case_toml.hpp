// rupture/input/case_toml.hpp
// TOML -> Case. All input validation lives here: every problem (unknown key, wrong type,
// value out of range, inconsistent geometry) raises InputError naming the key, the value and
// what is allowed, before any work starts. `--set key=value` overrides are applied to the
// parsed document first and validated the same way.
#pragma once
#include <string>
#include <vector>

#include "input/case.hpp"

namespace rupture {

// Reads and validates a case file, after applying overrides of the form "a.b.c=value"
// (value parsed as a TOML value, else taken as a string).
Case load_case(const std::string& path, const std::vector<std::string>& overrides = {});

// Same, from TOML text (tests, embedded examples). `origin` names the source in messages.
Case parse_case(const std::string& toml_text, const std::vector<std::string>& overrides = {},
                const std::string& origin = "<string>");

}  // namespace rupture
