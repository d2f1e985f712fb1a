// rupture/input/toml_section.hpp
// Validation helpers shared by the per-table parsers of input/case_toml: a Section is a view of
// one TOML table that checks types and reports unknown keys (with a did-you-mean hint); fail()
// raises the InputError every bad value gets, naming the key, the value and what is allowed.
// Internal to input/.
#pragma once
#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "input/names.hpp"

namespace rupture {

// Levenshtein distance between two keys (for "did you mean" hints).
std::size_t edit_distance(const std::string& a, const std::string& b);

inline std::string show(const toml::node& n) {
  std::ostringstream os;
  if (auto s = n.as_string()) {
    os << '"' << s->get() << '"';
  } else if (n.is_table()) {
    os << "{...}";
  } else {
    n.visit([&os](const auto& v) { os << v; });
  }
  return os.str();
}

[[noreturn]] inline void fail(const std::string& key, const std::string& value,
                              const std::string& rule) {
  throw InputError(fmt::format("input key '{}' = {}: {}", key, value, rule));
}

[[noreturn]] inline void fail(const std::string& key, double value, const std::string& rule) {
  fail(key, fmt::format("{:g}", value), rule);
}

// A view of one TOML table that records which keys were read, so that unknown keys
// (typos) are reported instead of silently ignored.
class Section {
 public:
  // `allowed` lists the keys this table may hold; empty = any key (tables of named entries).
  // Unknown keys are reported at once, before any value is read.
  Section(const toml::table& t, std::string path, std::vector<std::string> allowed = {})
      : t_(t), path_(std::move(path)) {
    if (allowed.empty()) return;
    for (const auto& [k, v] : t_) {
      const std::string name(k.str());
      if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
      std::string hint;
      for (const std::string& a : allowed)
        if (edit_distance(a, name) <= 2) hint = " (did you mean '" + key(a) + "'?)";
      fail(key(name), show(v), "unknown key" + hint + "; allowed here: " + join(allowed));
    }
  }

  // The dotted key of `k` for messages (a name with odd bytes shown escaped: input/names.hpp).
  std::string key(const std::string& k) const {
    return path_.empty() ? printable(k) : path_ + "." + printable(k);
  }
  bool has(const std::string& k) const { return t_.contains(k); }
  const toml::node* node(const std::string& k) const { return t_.get(k); }

  double number(const std::string& k) {
    const toml::node* n = node(k);
    if (!n) fail(key(k), "(missing)", "required, a number");
    if (auto v = n->value<double>(); v && (n->is_floating_point() || n->is_integer())) {
      if (!std::isfinite(*v)) fail(key(k), show(*n), "must be a finite number");
      return *v;
    }
    fail(key(k), show(*n), "must be a number");
  }
  double number(const std::string& k, double fallback) { return has(k) ? number(k) : fallback; }

  long integer(const std::string& k, long fallback) {
    const toml::node* n = node(k);
    if (!n) return fallback;
    if (!n->is_integer()) fail(key(k), show(*n), "must be an integer");
    return long(*n->value<std::int64_t>());
  }

  bool boolean(const std::string& k, bool fallback) {
    const toml::node* n = node(k);
    if (!n) return fallback;
    if (!n->is_boolean()) fail(key(k), show(*n), "must be true or false");
    return *n->value<bool>();
  }

  std::string string(const std::string& k, const std::string& fallback,
                     const std::vector<std::string>& allowed = {}) {
    const toml::node* n = node(k);
    if (!n) {
      if (fallback.empty() && !allowed.empty())
        fail(key(k), "(missing)", "required, one of " + join(allowed));
      return fallback;
    }
    if (!n->is_string()) fail(key(k), show(*n), "must be a string");
    std::string v = n->as_string()->get();
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), v) == allowed.end())
      fail(key(k), show(*n), "must be one of " + join(allowed));
    return v;
  }

  // A 2-vector [a, b] of numbers.
  void pair(const std::string& k, double out[2], bool required) {
    const toml::node* n = node(k);
    if (!n) {
      if (required) fail(key(k), "(missing)", "required, an array of two numbers [x, y]");
      return;
    }
    const toml::array* a = n->as_array();
    if (!a || a->size() != 2) fail(key(k), show(*n), "must be an array of two numbers [x, y]");
    for (std::size_t i = 0; i < 2; ++i) {
      auto v = (*a)[i].value<double>();
      if (!v || !std::isfinite(*v))
        fail(key(k), show(*n), "must be an array of two finite numbers");
      out[i] = *v;
    }
  }

  std::vector<std::string> strings(const std::string& k) {
    std::vector<std::string> out;
    const toml::node* n = node(k);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a) fail(key(k), show(*n), "must be an array of strings");
    for (const auto& e : *a) {
      if (!e.is_string()) fail(key(k), show(*n), "must be an array of strings");
      out.push_back(e.as_string()->get());
    }
    return out;
  }

  Section table(const std::string& k, bool required, std::vector<std::string> allowed = {}) {
    static const toml::table empty;
    const toml::node* n = node(k);
    if (!n) {
      if (required) fail(key(k), "(missing)", "required table [" + key(k) + "]");
      return Section(empty, key(k));
    }
    if (!n->is_table()) fail(key(k), show(*n), "must be a table");
    return Section(*n->as_table(), key(k), std::move(allowed));
  }

  const toml::table& raw() const { return t_; }

  static std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + ("\"" + v[i] + "\"");
    return s.empty() ? "(none)" : s;
  }

 private:
  const toml::table& t_;
  std::string path_;
};

inline bool inside(double a, double lo, double hi, double tol) {
  return a >= lo - tol && a <= hi + tol;
}

inline bool whole_cells(double length, double h) {
  const double n = length / h;
  return std::fabs(n - std::round(n)) <= 1e-6 * std::max(1.0, n);
}

// The entries of a table in the order the input file wrote them (toml++ keeps tables sorted by
// name): bodies, fields and interfaces are numbered and reported in input order. Entries added
// by --set (no source position) come last, in name order.
std::vector<std::pair<std::string, const toml::node*>> in_input_order(const toml::table& t);

// The named entries of a table ([bodies.NAME], [interface.NAME], ...) in input order, each name
// checked against the rule of input/names.hpp (InputError naming the entry otherwise).
std::vector<std::pair<std::string, const toml::node*>> named_entries(const Section& s);

}  // namespace rupture
