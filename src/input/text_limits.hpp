// rupture/input/text_limits.hpp
// Bounds on the text rupture reads before any parser sees it, so that no input can exhaust the
// stack or the memory of the TOML library: a case (file, checkpoint copy or --set value) is at
// most kMaxCaseBytes, nests arrays and inline tables at most kMaxTomlNesting deep and writes
// keys of at most kMaxKeyParts dotted parts. Files are read only when they are regular files
// (not a FIFO, a device or a directory) no larger than the bound given. Violations raise
// InputError naming the file or key, the value and the bound.
#pragma once
#include <cstddef>
#include <string>

namespace rupture {

inline constexpr std::size_t kMaxCaseBytes = std::size_t(64) << 20;  // 64 MiB
inline constexpr int kMaxTomlNesting = 32;
inline constexpr int kMaxKeyParts = 32;

// Throws InputError unless `text` (named `origin` in messages) keeps within the bounds above.
// A lexical scan (strings, literal strings, multi-line strings and comments skipped): it
// counts the open brackets and braces and the dots of each key (before its '=', or in a table
// header), never the dots of values.
void check_toml_limits(const std::string& text, const std::string& origin);

// The whole of `path` as text; InputError when it is missing, not a regular file (after
// following links) or larger than `max_bytes` (`what` names it in messages: "case file").
std::string read_bounded_file(const std::string& path, std::size_t max_bytes, const std::string& what);

}  // namespace rupture
