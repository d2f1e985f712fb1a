// rupture/input/parse_time_function.cpp
// `function` and its keys in a [boundary.X] or [loads.X] table (bc/time_function.hpp):
//   function = "constant" | "trapezoid" | "smooth_ramp" | "ricker" | "table"
//   rise_time (trapezoid, smooth_ramp), plateau_time, fall_time (trapezoid),
//   frequency, delay (ricker)
//   table = [[t0, v0], [t1, v1], ...] or table_file = "path.csv" (table)
// A CSV file has two columns time,value (comma or blank separated), an optional header line and
// '#' comments; a relative path is relative to the case file's directory. The values read are
// recorded in ParseContext::file_tables, so the input echo (run.json) holds them inline.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "input/case_parse.hpp"
#include "input/text_limits.hpp"

namespace rupture {

namespace {

std::string show_rows(const std::vector<double>& t, const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t k = 0; k < t.size() && k < 4; ++k)
    s += fmt::format("{}[{:g}, {:g}]", k ? ", " : "", t[k], v[k]);
  return s + (t.size() > 4 ? ", ...]" : "]");
}

// Parses "a,b" / "a b" into two finite numbers.
bool two_numbers(std::string line, double& a, double& b) {
  for (char& ch : line)
    if (ch == ',' || ch == ';' || ch == '\t') ch = ' ';
  std::istringstream in(line);
  std::string rest;
  if (!(in >> a >> b) || (in >> rest)) return false;
  return std::isfinite(a) && std::isfinite(b);
}

void read_table_file(const std::string& key, const std::string& given, const std::string& path,
                     std::vector<double>& t, std::vector<double>& v, std::vector<int>& lines) {
  std::string text;
  try {  // a regular file of bounded size (input/text_limits.hpp)
    text = read_bounded_file(path, kMaxCaseBytes, "table file");
  } catch (const InputError& e) {
    fail(key, "\"" + printable(given) + "\"", e.what());
  }
  std::istringstream in(text);
  std::string line;
  int number = 0;
  bool first = true;
  while (std::getline(in, line)) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    double a = 0, b = 0;
    if (!two_numbers(line, a, b)) {
      if (first) {  // a header line
        first = false;
        continue;
      }
      fail(key, "\"" + given + "\"",
           fmt::format("line {} of '{}' is not two numbers time,value: \"{}\"", number, path, line));
    }
    first = false;
    t.push_back(a), v.push_back(b), lines.push_back(number);
  }
}

}  // namespace

TimeFunction parse_time_function(Section& b, const std::string& value_key,
                                 const std::vector<std::string>& path, ParseContext& ctx) {
  TimeFunction f;
  const std::string fn =
      b.string("function", "constant", {"constant", "trapezoid", "smooth_ramp", "ricker", "table"});
  const bool is_table = fn == "table";
  if (value_key.empty()) {
    f.value = 1.0;  // a dimensionless factor
  } else if (is_table) {
    if (b.has(value_key))
      fail(b.key(value_key), show(*b.node(value_key)),
           "not used with function = \"table\": the table holds the values");
  } else {
    f.value = b.number(value_key);
  }
  if (fn != "ricker")
    for (const char* key : {"frequency", "delay"})
      if (b.has(key)) fail(b.key(key), show(*b.node(key)), "only allowed with function = \"ricker\"");
  if (fn == "ricker") {
    f.kind = TimeFunction::Kind::ricker;
    f.frequency = b.number("frequency");
    if (!(f.frequency > 0) || !std::isfinite(f.frequency))
      fail(b.key("frequency"), f.frequency, "must be > 0 and finite (Hz, the wavelet's peak frequency)");
    f.delay = b.number("delay");
    if (!(f.delay >= 0) || !std::isfinite(f.delay))
      fail(b.key("delay"), f.delay, "must be >= 0 and finite (s, the wavelet's centre)");
  }
  if (fn == "trapezoid") {
    f.kind = TimeFunction::Kind::trapezoid;
    f.rise_time = b.number("rise_time");
    if (f.rise_time <= 0) fail(b.key("rise_time"), f.rise_time, "must be > 0 (s)");
    f.plateau_time = b.number("plateau_time");
    if (f.plateau_time < 0) fail(b.key("plateau_time"), f.plateau_time, "must be >= 0 (s)");
    f.fall_time = b.number("fall_time");
    if (f.fall_time <= 0) fail(b.key("fall_time"), f.fall_time, "must be > 0 (s)");
  } else if (fn == "smooth_ramp") {
    f.kind = TimeFunction::Kind::smooth_ramp;
    f.rise_time = b.number("rise_time");
    if (f.rise_time <= 0) fail(b.key("rise_time"), f.rise_time, "must be > 0 (s)");
    for (const char* key : {"plateau_time", "fall_time"})
      if (b.has(key))
        fail(b.key(key), show(*b.node(key)), "only allowed with function = \"trapezoid\"");
  } else {
    if (b.has("rise_time"))
      fail(b.key("rise_time"), show(*b.node("rise_time")),
           "only allowed with function = \"trapezoid\" or \"smooth_ramp\"");
    for (const char* key : {"plateau_time", "fall_time"})
      if (b.has(key))
        fail(b.key(key), show(*b.node(key)), "only allowed with function = \"trapezoid\"");
  }
  if (!is_table) {
    for (const char* key : {"table", "table_file"})
      if (b.has(key)) fail(b.key(key), show(*b.node(key)), "only allowed with function = \"table\"");
    return f;
  }

  // function = "table": points inline or from a file.
  if (b.has("table") == b.has("table_file"))
    fail(b.key("table"), b.has("table") ? show(*b.node("table")) : "(missing)",
         fmt::format("function = \"table\" needs exactly one of {} = [[t0, v0], [t1, v1], ...] or "
                     "{} = \"path.csv\"",
                     b.key("table"), b.key("table_file")));
  std::vector<double> t, v;
  std::vector<int> rows;  // row (inline, from 1) or line (file) of each point, for messages
  std::string key;
  if (b.has("table")) {
    key = b.key("table");
    const toml::node* n = b.node("table");
    const toml::array* a = n->as_array();
    const std::string rule = "must be an array of [time, value] pairs of finite numbers";
    if (!a) fail(key, show(*n), rule);
    for (std::size_t k = 0; k < a->size(); ++k) {
      const toml::array* row = (*a)[k].as_array();
      if (!row || row->size() != 2) fail(key, show(*n), fmt::format("{}; row {} is not", rule, k + 1));
      const auto tk = (*row)[0].value<double>(), vk = (*row)[1].value<double>();
      if (!tk || !vk || !std::isfinite(*tk) || !std::isfinite(*vk))
        fail(key, show(*n), fmt::format("{}; row {} is not", rule, k + 1));
      t.push_back(*tk), v.push_back(*vk), rows.push_back(int(k + 1));
    }
  } else {
    key = b.key("table_file");
    const std::string given = b.string("table_file", "");
    std::filesystem::path file(given);
    if (file.is_relative() && !ctx.case_dir.empty()) file = std::filesystem::path(ctx.case_dir) / file;
    read_table_file(key, given, file.string(), t, v, rows);
    ctx.file_tables.push_back({path, t, v});
  }
  const char* where = b.has("table") ? "row" : "line";
  if (t.size() < 2)
    fail(key, show_rows(t, v), fmt::format("a table needs at least two points (it has {})", t.size()));
  for (std::size_t k = 1; k < t.size(); ++k)
    if (!(t[k] > t[k - 1]))
      fail(key, show_rows(t, v),
           fmt::format("times must increase strictly: {} {} has t = {:g} s after t = {:g} s at {} {}",
                       where, rows[k], t[k], t[k - 1], where, rows[k - 1]));
  f.set_table(std::move(t), std::move(v), 1.0);
  return f;
}

}  // namespace rupture
