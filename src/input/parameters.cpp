// rupture/input/parameters.cpp
#include "input/parameters.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "input/toml_section.hpp"

namespace rupture {
namespace {

constexpr int kMaxDepth = 64;

std::string known(const std::map<std::string, double>& names) {
  if (names.empty()) return "no [parameters] are defined";
  std::string s = "the parameters are";
  for (const auto& [n, v] : names) s += " " + n;
  return s;
}

// Recursive descent over the grammar of the header; every failure names the key and the text.
class Parser {
 public:
  Parser(std::string_view text, const std::map<std::string, double>& names, const std::string& key)
      : s_(text), names_(names), key_(key) {}

  double parse() {
    const double v = expression(0);
    skip();
    if (i_ != s_.size()) error(fmt::format("unexpected '{}' at character {}", s_[i_], i_ + 1));
    return v;
  }

 private:
  [[noreturn]] void error(const std::string& why) const {
    fail(key_, "\"=" + std::string(s_) + "\"", "the expression: " + why);
  }
  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool take(char c) {
    skip();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  void deeper(int depth) const {
    if (depth > kMaxDepth) error(fmt::format("nested deeper than {}", kMaxDepth));
  }
  double expression(int depth) {
    deeper(depth);
    double v = term(depth + 1);
    for (;;) {
      if (take('+')) v += term(depth + 1);
      else if (take('-')) v -= term(depth + 1);
      else return v;
    }
  }
  double term(int depth) {
    double v = factor(depth + 1);
    for (;;) {
      if (take('*')) v *= factor(depth + 1);
      else if (take('/')) v /= factor(depth + 1);
      else return v;
    }
  }
  double factor(int depth) {
    deeper(depth);
    if (take('-')) return -factor(depth + 1);
    if (take('+')) return factor(depth + 1);
    const double base = primary(depth + 1);
    if (take('^')) return std::pow(base, factor(depth + 1));
    return base;
  }
  double primary(int depth) {
    deeper(depth);
    skip();
    if (i_ >= s_.size()) error("ends where a value was expected");
    if (take('(')) {
      const double v = expression(depth + 1);
      if (!take(')')) error("a '(' is not closed");
      return v;
    }
    const char c = s_[i_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t at = i_;
      while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) ++i_;
      const std::string name(s_.substr(at, i_ - at));
      if (take('(')) {
        const double x = expression(depth + 1);
        if (!take(')')) error(fmt::format("{}( is not closed", name));
        if (name == "sqrt") return std::sqrt(x);
        if (name == "sin") return std::sin(x);
        if (name == "cos") return std::cos(x);
        if (name == "tan") return std::tan(x);
        if (name == "atan") return std::atan(x);
        if (name == "exp") return std::exp(x);
        if (name == "log") return std::log(x);
        if (name == "abs") return std::fabs(x);
        error(fmt::format("unknown function '{}' (sqrt, sin, cos, tan, atan, exp, log, abs)", name));
      }
      if (const auto it = names_.find(name); it != names_.end()) return it->second;
      if (name == "pi") return std::numbers::pi;
      error(fmt::format("unknown name '{}' ({})", name, known(names_)));
    }
    error(fmt::format("unexpected '{}' at character {}", c, i_ + 1));
  }
  double number() {
    // digits [. digits] [e [+-] digits]: parsed from a bounded copy (strtod needs a terminator).
    const std::size_t at = i_;
    auto digits = [&] {
      while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
    };
    digits();
    if (i_ < s_.size() && s_[i_] == '.') ++i_, digits();
    if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      ++i_;
      if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
      const std::size_t exp_at = i_;
      digits();
      if (i_ == exp_at) error("an exponent without digits");
    }
    const std::string text(s_.substr(at, i_ - at));
    if (text == ".") error("a '.' without digits");
    return std::strtod(text.c_str(), nullptr);
  }

  std::string_view s_;
  const std::map<std::string, double>& names_;
  const std::string& key_;
  std::size_t i_ = 0;
};

// An expression's value as the node that replaces its string: an integer when it is whole.
struct Value {
  bool whole = false;
  std::int64_t i = 0;
  double d = 0.0;
};
std::optional<Value> expression_of(const toml::node& n, const std::string& key,
                                   const std::map<std::string, double>& names) {
  const std::string& text = n.as_string()->get();
  if (text.empty() || text[0] != '=') return std::nullopt;
  const double v = evaluate_expression(std::string_view(text).substr(1), names, key);
  Value out;
  out.d = v;
  // Whole, or within round-off of a whole number of at least 1 (0.019 / 1e-3 for segments); a
  // small value stays a float however close to 0 it is.
  const double r = std::round(v);
  const bool whole = v == r || (std::fabs(v) >= 0.5 && std::fabs(v - r) <= 1e-9 * std::fabs(v));
  if (whole && std::fabs(r) < 9007199254740992.0) out.whole = true, out.i = static_cast<std::int64_t>(r);
  return out;
}

void walk(toml::node& n, const std::string& key, const std::map<std::string, double>& names, int depth) {
  if (depth > kMaxDepth) return;  // the TOML limits (input/text_limits) keep real input far shallower
  if (toml::table* t = n.as_table()) {
    std::vector<std::pair<std::string, Value>> found;  // replaced after the walk over the table
    for (auto&& [k, v] : *t) {
      const std::string name(k.str());
      // The top level: every table but [parameters] (numbers only), every string but the title.
      if (depth == 0 && (name == "parameters" || name == "title")) continue;
      const std::string sub = key.empty() ? name : key + "." + name;
      if (!v.is_string()) {
        walk(v, sub, names, depth + 1);
      } else {
        if (const std::optional<Value> x = expression_of(v, printable(sub), names)) found.emplace_back(name, *x);
      }
    }
    for (const auto& [name, x] : found) {
      if (x.whole) t->insert_or_assign(name, x.i);
      else t->insert_or_assign(name, x.d);
    }
  } else if (toml::array* a = n.as_array()) {
    for (std::size_t i = 0; i < a->size(); ++i) {
      toml::node& e = *a->get(i);
      const std::string sub = fmt::format("{}[{}]", key, i);
      if (!e.is_string()) {
        walk(e, sub, names, depth + 1);
        continue;
      }
      const std::optional<Value> x = expression_of(e, printable(sub), names);
      if (!x) continue;
      const auto at = a->cbegin() + std::ptrdiff_t(i);
      if (x->whole) a->replace(at, x->i);
      else a->replace(at, x->d);
    }
  }
}

}  // namespace

double evaluate_expression(std::string_view text, const std::map<std::string, double>& names,
                           const std::string& key) {
  Parser p(text, names, key);
  const double v = p.parse();
  if (!std::isfinite(v))
    fail(key, "\"=" + std::string(text) + "\"", fmt::format("the expression's value is {} (must be finite)", v));
  return v;
}

void substitute_parameters(toml::table& root) {
  std::map<std::string, double> names;
  if (toml::node* p = root.get("parameters")) {
    toml::table* t = p->as_table();
    if (!t) fail("parameters", show(*p), "must be a table of named numbers ([parameters] with NAME = value)");
    std::map<std::string, std::string> pending;  // name -> expression (without '='), by name
    for (auto&& [k, v] : *t) {
      const std::string name(k.str());
      const std::string key = "parameters." + printable(name);
      bool word = !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
      for (char c : name) word = word && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
      if (!word) fail(key, show(v), "a parameter's name is a letter or '_' followed by letters, digits or '_'");
      if (name == "pi") fail(key, show(v), "'pi' is the constant 3.14159...; name the parameter otherwise");
      if (const toml::value<std::string>* e = v.as_string(); e && !e->get().empty() && e->get()[0] == '=') {
        pending[name] = e->get().substr(1);
        continue;
      }
      const std::optional<double> x = v.value<double>();
      if (!(v.is_floating_point() || v.is_integer()) || !x || !std::isfinite(*x))
        fail(key, show(v), "must be a finite number, or an '='-expression of the other parameters");
      names[name] = *x;
    }
    // A parameter may be an expression of others, in any order: resolved in passes, each taking
    // those whose names are all known by then; what is left depends on itself.
    while (!pending.empty()) {
      std::map<std::string, double> done;
      for (const auto& [name, text] : pending) {
        try {
          done[name] = evaluate_expression(text, names, "parameters." + name);
        } catch (const InputError&) {
        }
      }
      if (done.empty()) {
        const auto& [name, text] = *pending.begin();
        std::string others;
        for (const auto& [n, e] : pending) others += (others.empty() ? "" : ", ") + n;
        std::map<std::string, double> all = names;
        for (const auto& [n, e] : pending) all[n] = 0.0;
        evaluate_expression(text, all, "parameters." + name);  // its own error, if it has one
        fail("parameters." + name, "\"=" + text + "\"",
             "the parameters " + others + " depend on one another in a circle");
      }
      for (const auto& [name, v] : done) names[name] = v, pending.erase(name);
    }
  }
  walk(root, "", names, 0);
}

}  // namespace rupture
