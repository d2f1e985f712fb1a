// rupture/input/input_schema.hpp
// One description of every table and key of the input file: type, SI unit, default, allowed
// range, meaning and an example. The parsers take each table's allowed keys from it
// (allowed_keys), `rupture check --explain KEY` prints one entry and `rupture docs --input` the
// whole reference (docs/input.md), so the validator, the CLI and the docs cannot drift apart.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace rupture {

// A path names a key by its tables: "time.cfl". '*' stands for a user-chosen name
// ("interface.*.sigma_max"), "[]" for each element of an array of tables
// ("bodies.*.minus[].radius"); "" is the top level of the file.
struct KeyDoc {
  std::string path;
  std::string type;           // "number", "integer", "boolean", "string", "[x, y]", "table", ...
  std::string unit;           // SI; "" when dimensionless or not a quantity
  std::string default_value;  // TOML text, "required", or "depends: ..."
  std::string range;          // allowed values, in the words of the validator's message
  std::string description;    // one line
  std::string example;        // a TOML value ("" for tables)
  // "" always allowed; "KEY = a | b": only when the sibling KEY has one of these values (a
  // variant: a shape's or a law's keys); any other text describes the case in words.
  std::string when = "";

  bool is_table() const;
  // Where this table's keys live: `path`, or `path` + "[]" for an array of tables.
  std::string table_path() const;
  std::string name() const;  // the last component of the path
};

// Every entry, tables before their keys, keys in the order the parsers list them.
const std::vector<KeyDoc>& input_schema();

// The keys documented directly under the table `table` ("" the top level, "grid",
// "interface.*", "bodies.*.minus[]"), in schema order: the allowed-key list of that table.
std::vector<std::string> allowed_keys(const std::string& table);
// Those of them allowed when the key `selector` has `value`: keys whose `when` is about
// another key (or nothing) stay, "selector = ..." keys stay only if they list `value`.
std::vector<std::string> allowed_keys(const std::string& table, const std::string& selector,
                                      const std::string& value);
// Only the keys that belong to `selector = value` (when = "selector = ... value ...").
std::vector<std::string> variant_keys(const std::string& table, const std::string& selector,
                                      const std::string& value);

// The entry of a key or table. Concrete names match '*' ("interface.weak_plane.sigma_max" is
// "interface.*.sigma_max") and an index matches "[]" ("bodies.b.minus[0].radius"); a literal
// component is preferred to '*'. nullptr if none matches.
const KeyDoc* find_key(const std::string& path);
// Schema paths close to an unknown `path`, best first (for a did-you-mean list).
std::vector<std::string> similar_keys(const std::string& path, std::size_t max_count = 8);

// One entry as plain text (`rupture check --explain`); a table lists its keys.
std::string explain_key(const KeyDoc& entry);
// The whole reference as Markdown: docs/input.md is this text (`rupture docs --input`).
std::string input_reference_markdown();

// The keys of a TOML document (concrete paths, "bodies.plate.minus[0].center") that no entry
// documents; the text must parse as TOML (throws InputError otherwise).
std::vector<std::string> undocumented_keys(const std::string& toml_text);

}  // namespace rupture
