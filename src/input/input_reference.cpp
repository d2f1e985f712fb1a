// rupture/input/input_reference.cpp
// Reading the key table of input/input_schema.cpp: the allowed keys of a table for the parsers,
// the entry of a concrete key (--explain), near misses, the Markdown reference (docs/input.md)
// and the keys of a file that no entry documents.
#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <sstream>

#include "core/errors.hpp"
#include "input/input_schema.hpp"
#include "input/toml_section.hpp"

namespace rupture {

bool KeyDoc::is_table() const {
  return type == "table" || type == "named tables" || type == "array of tables";
}

std::string KeyDoc::table_path() const {
  return type == "array of tables" ? path + "[]" : path;
}

std::string KeyDoc::name() const {
  const std::size_t dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

namespace {

std::string parent_of(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  return dot == std::string::npos ? "" : path.substr(0, dot);
}

std::vector<const KeyDoc*> children(const std::string& table) {
  std::vector<const KeyDoc*> out;
  for (const KeyDoc& e : input_schema())
    if (!e.path.empty() && parent_of(e.path) == table) out.push_back(&e);
  return out;
}

// `when` = "selector = a | b": whether it is about `selector`, and if so whether it admits value.
bool about(const KeyDoc& e, const std::string& selector) {
  return e.when.rfind(selector + " = ", 0) == 0;
}
bool admits(const KeyDoc& e, const std::string& selector, const std::string& value) {
  std::stringstream values(e.when.substr(selector.size() + 3));
  for (std::string v; std::getline(values, v, '|');) {
    v.erase(0, v.find_first_not_of(' '));
    v.erase(v.find_last_not_of(' ') + 1);
    if (v == value) return true;
  }
  return false;
}

// "bodies.b.minus[0].radius" -> {"bodies", "b", "minus[]", "radius"}
std::vector<std::string> components(const std::string& path) {
  std::vector<std::string> out;
  if (path.empty()) return out;
  std::stringstream ss(path);
  for (std::string c; std::getline(ss, c, '.');) {
    const std::size_t open = c.find('[');
    if (open != std::string::npos && c.back() == ']') c = c.substr(0, open) + "[]";
    out.push_back(c);
  }
  if (path.back() == '.') out.push_back("");
  return out;
}

std::string heading(const KeyDoc& t) {
  if (t.path.empty()) return "Top level";
  return t.type == "array of tables" ? "[[" + t.path + "]]" : "[" + t.path + "]";
}

std::string unit_of(const KeyDoc& e) {
  return e.unit.empty() ? "-" : e.unit;
}

std::string applies(const KeyDoc& e) {
  return e.when.empty() ? "" : "only with " + e.when;
}

// A TOML value (shown as code) rather than words ("required", "depends: ...").
bool is_value(const std::string& s) {
  if (s.empty()) return false;
  const char c = s[0];
  if (std::isdigit(static_cast<unsigned char>(c)) || c == '"' || c == '[' || c == '-') return true;
  return s == "true" || s == "false";
}

std::string cell(std::string s) {
  std::string out;
  for (const char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string code_or_words(const std::string& s) {
  if (!is_value(s)) return s;
  const std::size_t space = s.find(" (");  // "0 (no refinement)"
  if (space == std::string::npos) return fmt::format("`{}`", s);
  return fmt::format("`{}`{}", s.substr(0, space), s.substr(space));
}

// "Description — default; range." for the Markdown reference.
std::string summary(const KeyDoc& t) {
  return fmt::format("{} — {}{}.\n\n", t.description, t.default_value,
                     t.range.empty() ? "" : "; " + t.range);
}

// The table whose section documents `t`: its entries' table for a collection of named tables.
const KeyDoc& section_of(const KeyDoc& t) {
  for (const KeyDoc& e : input_schema())
    if (e.path == t.path + ".*") return e;
  return t;
}

}  // namespace

std::vector<std::string> allowed_keys(const std::string& table) {
  std::vector<std::string> keys;
  for (const KeyDoc* e : children(table)) keys.push_back(e->name());
  return keys;
}

std::vector<std::string> allowed_keys(const std::string& table, const std::string& selector,
                                      const std::string& value) {
  std::vector<std::string> keys;
  for (const KeyDoc* e : children(table))
    if (!about(*e, selector) || admits(*e, selector, value)) keys.push_back(e->name());
  return keys;
}

std::vector<std::string> variant_keys(const std::string& table, const std::string& selector,
                                      const std::string& value) {
  std::vector<std::string> keys;
  for (const KeyDoc* e : children(table))
    if (about(*e, selector) && admits(*e, selector, value)) keys.push_back(e->name());
  return keys;
}

const KeyDoc* find_key(const std::string& path) {
  const std::vector<std::string> want = components(path);
  const KeyDoc* best = nullptr;
  long best_literal = -1;
  for (const KeyDoc& e : input_schema()) {
    const std::vector<std::string> have = components(e.path);
    if (have.size() != want.size()) continue;
    long literal = 0;
    bool ok = true;
    for (std::size_t i = 0; ok && i < have.size(); ++i) {
      if (have[i] == want[i])
        ++literal;
      else
        ok = have[i] == "*" && !want[i].empty();
    }
    if (ok && literal > best_literal) best = &e, best_literal = literal;
  }
  return best;
}

std::vector<std::string> similar_keys(const std::string& path, std::size_t max_count) {
  const std::vector<std::string> want = components(path);
  const std::string last = want.empty() ? "" : want.back();
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const KeyDoc& e : input_schema()) {
    if (e.path.empty()) continue;
    // The entry with the query's own names in place of '*', compared as a whole; and its last
    // component alone (a key given without its table: "cfl").
    std::vector<std::string> have = components(e.path);
    std::string filled;
    for (std::size_t i = 0; i < have.size(); ++i)
      filled += (i ? "." : "") + (have[i] == "*" && i < want.size() ? want[i] : have[i]);
    std::string normal;
    for (std::size_t i = 0; i < want.size(); ++i) normal += (i ? "." : "") + want[i];
    const std::size_t whole = edit_distance(normal, filled);
    const bool prefix = last.size() >= 3 && have.back().rfind(last, 0) == 0;  // "sigma"
    const std::size_t key = prefix ? 1 : edit_distance(last, have.back());
    const std::size_t score = std::min(whole, key + 2);
    if (whole <= 2 || key <= std::max<std::size_t>(1, last.size() / 4))
      scored.push_back({score, e.path});
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (const auto& [score, p] : scored)
    if (out.size() < max_count) out.push_back(p);
  return out;
}

std::string explain_key(const KeyDoc& e) {
  std::string s;
  if (!e.is_table()) {
    s += fmt::format("{}  ({}{})\n", e.path, e.type, e.unit.empty() ? "" : ", " + e.unit);
    s += fmt::format("  meaning: {}\n", e.description);
    s += fmt::format("  default: {}\n", e.default_value);
    if (!e.range.empty()) s += fmt::format("  allowed: {}\n", e.range);
    if (!e.when.empty()) s += fmt::format("  applies: {}\n", applies(e));
    s += fmt::format("  example: {} = {}\n", e.name(), e.example);
    return s;
  }
  s += fmt::format("{}  ({})\n  {}\n", heading(e), e.type, e.description);
  if (!e.default_value.empty()) s += fmt::format("  default: {}\n", e.default_value);
  if (!e.range.empty()) s += fmt::format("  allowed: {}\n", e.range);
  const std::vector<const KeyDoc*> keys = children(e.table_path());
  std::size_t width = 0;
  for (const KeyDoc* k : keys) width = std::max(width, k->name().size());
  s += "  keys:\n";
  for (const KeyDoc* k : keys) {
    const std::string what =
        k->is_table() ? k->type : k->type + (k->unit.empty() ? "" : ", " + k->unit);
    s += fmt::format("    {:<{}}  {}: {}{}\n", k->name(), width, what, k->description,
                     k->when.empty() ? "" : " (" + applies(*k) + ")");
  }
  s += fmt::format("  one key: rupture check --explain {}{}KEY\n", e.table_path(),
                   e.path.empty() ? "" : ".");
  return s;
}

std::string input_reference_markdown() {
  std::string md =
      "# Input reference\n\n"
      "Generated by `rupture docs --input` from `src/input/input_schema.cpp`, the description the "
      "input validator uses; do not edit by hand. Regenerate with "
      "`build/release/bin/rupture docs --input > docs/input.md` (the test `input_reference_docs` "
      "fails while they differ).\n\n"
      "Every table and key a case file may hold, in SI units. In a path, `*` stands for a name "
      "you choose (`[interface.weak_plane]` is an `interface.*` table; every name, and a "
      "`bodies.*.field` name too, is 1 to 64 characters from A-Z a-z 0-9 _ -, since names become "
      "parts of file names in the run directory) and `[]` for each element "
      "of an array of tables (`[[bodies.plate.minus]]`). A key is required, has a default, or "
      "its default depends on other keys (\"depends: ...\"). A key with \"only with ...\" belongs "
      "to one variant (a shape, a law, a load type, a time function) and is an error elsewhere. "
      "`rupture check --explain KEY` prints one entry (`rupture check --explain "
      "interface.weak_plane.sigma_max`), `rupture check --explain TABLE` a table's keys. Any "
      "key not listed here is rejected (\"unknown key\", with a did-you-mean hint).\n";
  for (const KeyDoc& t : input_schema()) {
    if (!t.is_table()) continue;
    const std::vector<const KeyDoc*> keys = children(t.table_path());
    if (keys.size() == 1 && keys[0]->name() == "*") continue;  // described with its entries
    md += t.path.empty() ? fmt::format("\n## {}\n\n", heading(t))
                         : fmt::format("\n## `{}`\n\n", heading(t));
    if (t.name() == "*") {
      const KeyDoc* collection = find_key(parent_of(t.path));
      if (collection) md += summary(*collection);
    } else if (!t.path.empty() && (!t.default_value.empty() || !t.range.empty())) {
      md += summary(t);
    }
    if (t.name() == "*" || t.path.empty() || (t.default_value.empty() && t.range.empty()))
      md += t.description + "\n\n";
    md += "| key | type | unit | default | allowed | meaning | example |\n";
    md += "|---|---|---|---|---|---|---|\n";
    for (const KeyDoc* k : keys) {
      std::string meaning = k->description;
      if (!k->when.empty()) meaning = fmt::format("({}) {}", applies(*k), meaning);
      if (k->is_table()) meaning += fmt::format(" See `{}`.", heading(section_of(*k)));
      const std::string example = k->example.empty() ? "" : "`" + k->example + "`";
      md += fmt::format("| `{}` | {} | {} | {} | {} | {} | {} |\n", k->name(), cell(k->type),
                        cell(unit_of(*k)), cell(code_or_words(k->default_value)), cell(k->range),
                        cell(meaning), cell(example));
    }
  }
  return md;
}

std::vector<std::string> undocumented_keys(const std::string& toml_text) {
  toml::table root;
  try {
    root = toml::parse(toml_text);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("TOML syntax error: {}", e.description()));
  }
  std::vector<std::string> missing;
  auto walk = [&](auto& self, const toml::table& t, const std::string& prefix) -> void {
    for (const auto& [k, v] : t) {
      const std::string path =
          prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
      if (!find_key(path)) {
        missing.push_back(path);
        continue;
      }
      if (path == "parameters") continue;  // named numbers: any name (input/parameters.hpp)
      if (const toml::table* sub = v.as_table()) self(self, *sub, path);
      if (const toml::array* a = v.as_array(); a && a->is_array_of_tables())
        for (std::size_t i = 0; i < a->size(); ++i)
          self(self, *(*a)[i].as_table(), fmt::format("{}[{}]", path, i));
    }
  };
  walk(walk, root, "");
  return missing;
}

}  // namespace rupture
