// rupture/input/toml_section.cpp
#include "input/toml_section.hpp"

#include <limits>

namespace rupture {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

std::vector<std::pair<std::string, const toml::node*>> in_input_order(const toml::table& t) {
  struct Entry {
    std::size_t line, column;
    std::string name;
    const toml::node* node;
  };
  std::vector<Entry> e;
  for (const auto& [k, v] : t) {
    const auto& pos = k.source().begin;
    const bool known =
        pos.line > 0 && k.source().path && t.source().path && *k.source().path == *t.source().path;
    e.push_back({known ? std::size_t(pos.line) : std::numeric_limits<std::size_t>::max(),
                 known ? std::size_t(pos.column) : 0, std::string(k.str()), &v});
  }
  std::stable_sort(e.begin(), e.end(), [](const Entry& a, const Entry& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  std::vector<std::pair<std::string, const toml::node*>> out;
  for (const Entry& x : e) out.emplace_back(x.name, x.node);
  return out;
}

std::vector<std::pair<std::string, const toml::node*>> named_entries(const Section& s) {
  auto out = in_input_order(s.raw());
  for (const auto& [name, node] : out) check_name(s.key(name), name);
  return out;
}

}  // namespace rupture
