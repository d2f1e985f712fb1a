// rupture/input/names.hpp
// The names a user gives (materials, bodies, velocity fields, interfaces, stations, loads,
// boundary conditions, refine boxes) become parts of file names in the run directory
// (interface/NAME_000001.csv, crack_tip_NAME.csv, station_NAME.csv ...) and of printed
// `key=value` lines. So every name is checked at input against one documented rule, before
// any work: 1 to kMaxNameLength characters from A-Z a-z 0-9 _ - (no '/', '.', space, quote or
// control character can reach a path). `printable` shows any text safely in a message.
#pragma once
#include <string>

namespace rupture {

inline constexpr std::size_t kMaxNameLength = 64;
inline constexpr const char* kNameRule =
    "a name is 1 to 64 characters from A-Z a-z 0-9 _ - (it becomes part of file names in the "
    "run directory)";

// Whether `name` follows the rule above.
bool valid_name(const std::string& name);

// Throws InputError naming `key` (the entry or key that holds the name) unless valid_name.
void check_name(const std::string& key, const std::string& name);

// `text` with control characters, quotes, backslashes and bytes >= 0x80 written as \xNN (a
// NUL byte no longer cuts a message short), at most 200 characters then "...".
std::string printable(const std::string& text);

}  // namespace rupture
