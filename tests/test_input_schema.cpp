// Tests of input/input_schema: the key table is the validator's (every documented key is accepted
// by its table, every table rejects an undocumented key), the examples and test inputs use only
// documented keys, range texts say what the validator's messages say, and lookups of concrete
// keys (--explain) find their entries.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "input/input_schema.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

// A valid case with every table: a refined grid, two bodies (the lower one with a cut-out,
// last in the text so that its keys can be appended), a boundary condition, one load of each
// type and an interface.
std::string full_case_toml() {
  return R"(
title = "every table"
[model]
plane = "strain"
[materials.homalite]
youngs_modulus = 5.2e9
poisson_ratio = 0.34
density = 1246.0
[grid]
min = [0.0, -0.004]
max = [0.01, 0.004]
cell_size = 0.5e-3
coarse_cell_size = 1e-3
particles_per_cell = 2
[grid.refine.fine]
min = [0.0, -0.002]
max = [0.01, 0.002]
level = 1
[time]
end = 1e-6
[solver]
scheme = "MUSL"
[boundary.push]
edge = "left"
component = "x"
bodies = ["lower"]
velocity = 1.0
[loads.t]
type = "traction"
from = [0.0, 0.004]
to = [0.01, 0.004]
normal = 1e6
[loads.g]
type = "body_force"
acceleration = [0.0, -9.81]
[loads.v]
type = "velocity"
min = [0.0, 0.003]
max = [0.001, 0.004]
direction = [1.0, 0.0]
velocity = 1.0
bodies = ["upper"]
[loads.p]
type = "point_force"
point = [0.005, 0.002]
force = [0.0, 1.0]
function = "ricker"
frequency = 1e5
delay = 1e-5
[interface.weak]
upper_body = "upper"
lower_body = "lower"
y = 0.0
start = 0.002
end = 0.006
segments = 40
sigma_max = 24e6
delta_n = 0.4e-6
[output]
history_interval = 0.1e-6
[bodies.upper]
material = "homalite"
min = [0.0, 0.0]
max = [0.01, 0.004]
[bodies.lower]
material = "homalite"
min = [0.0, -0.004]
max = [0.01, 0.0]
[[bodies.lower.minus]]
shape = "circle"
center = [0.005, -0.003]
radius = 0.0006
)";
}

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_case(text, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The concrete tables of full_case_toml() that a schema table path stands for.
std::vector<std::string> instances(const std::string& table, const std::string& when = "") {
  if (table == "materials.*") return {"materials.homalite"};
  if (table == "grid.refine.*") return {"grid.refine.fine"};
  if (table == "bodies.*") return {"bodies.upper"};
  if (table == "bodies.*.minus[]") return {"bodies.lower.minus[0]"};
  if (table == "interface.*.stretches[]") return {"interface.weak.stretches[0]"};
  if (table == "interface.*.taper") return {"interface.weak.taper"};
  if (table == "interface.*.profile") return {"interface.weak.profile"};
  if (table == "boundary.*") return {"boundary.push"};
  if (table == "interface.*") return {"interface.weak"};
  if (table == "stations.*") return {"stations.st"};
  if (table == "loads.*") {
    if (when.find("type = traction") == 0) return {"loads.t"};
    if (when.find("type = body_force") == 0) return {"loads.g"};
    if (when.find("type = velocity") == 0) return {"loads.v"};
    if (when.find("type = point_force") == 0) return {"loads.p"};
    return {"loads.t", "loads.g", "loads.v", "loads.p"};
  }
  return {table};
}

// full_case_toml() with `key = value` in the table `table` (replacing the key if present).
// The cut-out is edited in the text (--set cannot reach into an array of tables).
std::string with_key(const std::string& table, const std::string& key, const std::string& value,
                     std::vector<std::string>& overrides) {
  std::string text = full_case_toml();
  if (table == "interface.weak.stretches[0]") {
    // The interface made a slip-weakening fault with one stretch, appended last.
    overrides = {"interface.weak.law=\"slip_weakening\"", "interface.weak.static_friction=0.6",
                 "interface.weak.dynamic_friction=0.4", "interface.weak.dc=1e-6",
                 "interface.weak.initial_traction=[-1e6, 0.1e6]"};
    for (const char* k : {"sigma_max = 24e6\n", "delta_n = 0.4e-6\n"})
      text.erase(text.find(k), std::string(k).size());
    std::string stretch = "[[interface.weak.stretches]]\n";
    for (const char* k : {"from = [0.003, 0.0]", "to = [0.004, 0.0]"})
      if (std::string(k).rfind(key + " =", 0) != 0) stretch += std::string(k) + "\n";
    return text + stretch + key + " = " + value + "\n";
  }
  if (table == "interface.weak.taper" || table == "interface.weak.profile") {
    // The interface made a rate-and-state fault with a taper (or a profile of b).
    for (const char* k : {"sigma_max = 24e6\n", "delta_n = 0.4e-6\n"})
      text.erase(text.find(k), std::string(k).size());
    overrides = {"interface.weak.law=\"rate_state\"", "interface.weak.a=0.008", "interface.weak.b=0.012",
                 "interface.weak.dc=1e-6", "interface.weak.initial_slip_rate=1e-12",
                 "interface.weak.initial_traction=[-1e6, 0.1e6]",
                 table == "interface.weak.taper"
                     ? "interface.weak.taper={centre=[0.0,0.0],half_width=0.001,width=0.001,a=0.016}"
                     : "interface.weak.profile={along=\"x\",b=[[0.0,0.012],[0.005,0.014]]}",
                 table + "." + key + "=" + value};
    return text;
  }
  if (table != "bodies.lower.minus[0]") {
    overrides = {(table.empty() ? "" : table + ".") + key + "=" + value};
    return text;
  }
  overrides.clear();
  const std::size_t minus = text.find("[[bodies.lower.minus]]");
  std::istringstream lines(text.substr(minus));
  std::string kept;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(key + " =", 0) != 0) kept += line + "\n";
  return text.substr(0, minus) + kept + key + " = " + value + "\n";
}

std::string parent_of(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  return dot == std::string::npos ? "" : path.substr(0, dot);
}

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream buf;
  buf << in.rdbuf();
  return buf.str();
}

}  // namespace

TEST(InputSchema, full_case_parses) {
  EXPECT_EQ(error_of(full_case_toml()), "");
}

// Every documented key, given a wrong value in a table that holds it, is judged by its value
// (or its variant), never reported as an unknown key.
TEST(InputSchema, every_documented_key_is_accepted_by_its_table) {
  int checked = 0;
  for (const KeyDoc& e : input_schema()) {
    if (e.path.empty()) continue;
    for (const std::string& table : instances(parent_of(e.path), e.when)) {
      std::vector<std::string> overrides;
      const std::string text = with_key(table, e.name(), "\"?\"", overrides);
      const std::string msg = error_of(text, overrides);
      EXPECT_EQ(msg.find("unknown key"), std::string::npos)
          << e.path << " in " << (table.empty() ? "(top level)" : table) << ": " << msg;
      ++checked;
    }
  }
  EXPECT_GT(checked, 130);
}

// Every table of the file is validated against its documented keys: an undocumented one is an
// error naming it.
TEST(InputSchema, every_table_rejects_an_undocumented_key) {
  for (const KeyDoc& t : input_schema()) {
    if (!t.is_table()) continue;
    const std::vector<std::string> keys = allowed_keys(t.table_path());
    if (keys.size() == 1 && keys[0] == "*") continue;  // named entries: any name
    if (t.table_path() == "parameters") continue;     // named numbers: any name (input/parameters.hpp)
    for (const std::string& table : instances(t.table_path())) {
      std::vector<std::string> overrides;
      const std::string text = with_key(table, "zz_undocumented", "1", overrides);
      const std::string msg = error_of(text, overrides);
      const std::string key = (table.empty() ? "" : table + ".") + "zz_undocumented";
      EXPECT_NE(msg.find("'" + key + "'"), std::string::npos) << key << ": " << msg;
      EXPECT_NE(msg.find("unknown key"), std::string::npos) << key << ": " << msg;
    }
  }
}

TEST(InputSchema, examples_and_test_inputs_use_only_documented_keys) {
  std::vector<std::pair<std::string, std::string>> inputs = {
      {"full_case_toml", full_case_toml()}, {"strip_case_toml", test::strip_case_toml()}};
  const std::filesystem::path examples = std::filesystem::path(RUPTURE_SOURCE_DIR) / "examples";
  for (const auto& f : std::filesystem::directory_iterator(examples))
    if (f.path().extension() == ".toml") inputs.push_back({f.path().string(), read_file(f.path())});
  ASSERT_GE(inputs.size(), 4u);
  for (const auto& [name, text] : inputs) {
    for (const std::string& k : undocumented_keys(text)) ADD_FAILURE() << name << ": " << k;
    if (name != "full_case_toml" && name != "strip_case_toml") {
      EXPECT_EQ(error_of(text), "") << name;  // and the validator accepts them
    }
  }
  const std::vector<std::string> odd = undocumented_keys("[grid]\ncel_size = 1\n");
  ASSERT_EQ(odd.size(), 1u);
  EXPECT_EQ(odd[0], "grid.cel_size");
}

// The range text of a key says what the validator's message says (up to the first ';').
TEST(InputSchema, range_text_matches_the_validator_message) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"time.cfl", "2"},
      {"time.cohesive_safety", "0"},
      {"time.end", "-1"},
      {"materials.homalite.poisson_ratio", "0.6"},
      {"materials.homalite.density", "0"},
      {"solver.flip", "2"},
      {"solver.threads", "-1"},
      {"grid.particles_per_cell", "9"},
      {"grid.refine.fine.level", "0"},
      {"grid.margin", "1"},
      {"interface.weak.segments", "0"},
      {"interface.weak.separation", "0"},
      {"interface.weak.r", "1"},
      {"interface.weak.q", "0"},
      {"loads.v.direction", "[0.0, 0.0]"},
      {"output.history_interval", "-1"},
      {"output.snapshot_interval", "-1"},
      {"output.progress_interval", "0"},
      {"output.interface_interval", "-1"},
  };
  for (const auto& [key, value] : bad) {
    const KeyDoc* e = find_key(key);
    ASSERT_NE(e, nullptr) << key;
    const std::string range = e->range.substr(0, e->range.find(';'));
    const std::string msg = error_of(full_case_toml(), {key + "=" + value});
    EXPECT_NE(msg.find("'" + key + "'"), std::string::npos) << msg;
    EXPECT_NE(msg.find(range), std::string::npos)
        << key << ": schema range '" << range << "' not in the message: " << msg;
  }
}

TEST(InputSchema, entries_are_complete_and_conditions_name_sibling_keys) {
  for (const KeyDoc& e : input_schema()) {
    EXPECT_FALSE(e.type.empty()) << e.path;
    EXPECT_FALSE(e.description.empty()) << e.path;
    if (e.is_table()) continue;
    EXPECT_FALSE(e.default_value.empty()) << e.path;
    EXPECT_FALSE(e.example.empty()) << e.path;
    if (e.type == "number") {
      EXPECT_FALSE(e.range.empty()) << e.path;
    }
    const std::size_t eq = e.when.find(" = ");
    if (eq != std::string::npos && e.when.find(' ') == eq) {
      const std::string sibling = parent_of(e.path) + "." + e.when.substr(0, eq);
      EXPECT_NE(find_key(sibling), nullptr) << e.path << ": when '" << e.when << "'";
    }
  }
  // Paths are unique.
  for (std::size_t i = 0; i < input_schema().size(); ++i)
    for (std::size_t j = i + 1; j < input_schema().size(); ++j)
      EXPECT_NE(input_schema()[i].path, input_schema()[j].path);
}

// The variant lists the parsers use keep their order (messages list them).
TEST(InputSchema, variant_key_lists) {
  using V = std::vector<std::string>;
  const V fn = {"function", "rise_time", "plateau_time", "fall_time", "frequency", "delay", "table",
                "table_file"};
  auto plus = [&](V v) {
    v.insert(v.end(), fn.begin(), fn.end());
    return v;
  };
  EXPECT_EQ(allowed_keys("loads.*", "type", "traction"),
            plus({"type", "from", "to", "traction", "normal", "shear", "bodies"}));
  EXPECT_EQ(allowed_keys("loads.*", "type", "body_force"),
            plus({"type", "acceleration", "bodies"}));
  EXPECT_EQ(allowed_keys("loads.*", "type", "velocity"),
            plus({"type", "min", "max", "direction", "velocity", "bodies"}));
  EXPECT_EQ(allowed_keys("loads.*", "type", "point_force"), plus({"type", "point", "force", "bodies"}));
  EXPECT_EQ(variant_keys("bodies.*.minus[]", "shape", "rectangle"), (V{"min", "max"}));
  EXPECT_EQ(variant_keys("bodies.*.minus[]", "shape", "ellipse"), (V{"center", "radii", "angle"}));
  EXPECT_EQ(allowed_keys(""), (V{"title", "parameters", "model", "materials", "grid", "bodies", "time", "solver",
                                 "absorbing", "boundary", "loads", "interface", "stations",
                                 "output"}));
}

TEST(InputSchema, concrete_keys_find_their_entries) {
  auto path_of = [](const std::string& k) {
    const KeyDoc* e = find_key(k);
    return e ? e->path : std::string("(none)");
  };
  EXPECT_EQ(path_of("interface.weak_plane.sigma_max"), "interface.*.sigma_max");
  EXPECT_EQ(path_of("interface.*.sigma_max"), "interface.*.sigma_max");
  EXPECT_EQ(path_of("bodies.plate.minus[2].radius"), "bodies.*.minus[].radius");
  EXPECT_EQ(path_of("bodies.plate.radius"), "bodies.*.radius");
  EXPECT_EQ(path_of("grid.refine"), "grid.refine");
  EXPECT_EQ(path_of("grid.refine.level3.level"), "grid.refine.*.level");
  EXPECT_EQ(path_of("time.cfl"), "time.cfl");
  EXPECT_EQ(path_of(""), "");
  EXPECT_EQ(path_of("time.cfll"), "(none)");
  EXPECT_EQ(path_of("interface.weak_plane.sigma"), "(none)");
  const std::vector<std::string> near = similar_keys("time.cfll");
  ASSERT_FALSE(near.empty());
  EXPECT_EQ(near[0], "time.cfl");
  const std::vector<std::string> bare = similar_keys("cfl");
  EXPECT_NE(std::find(bare.begin(), bare.end(), "time.cfl"), bare.end());
  const std::vector<std::string> named = similar_keys("interface.weak_plane.sigma");
  EXPECT_NE(std::find(named.begin(), named.end(), "interface.*.sigma_max"), named.end());
}

TEST(InputSchema, explain_shows_every_field) {
  const std::string s = explain_key(*find_key("interface.x.sigma_max"));
  for (const char* part :
       {"interface.*.sigma_max", "number, Pa", "default: required", "allowed: > 0",
        "only with law = xu_needleman | bilinear", "example: sigma_max = 24e6"})
    EXPECT_NE(s.find(part), std::string::npos) << part << " not in:\n" << s;
  const std::string t = explain_key(*find_key("grid"));
  for (const char* part : {"[grid]", "cell_size", "refine", "margin"})
    EXPECT_NE(t.find(part), std::string::npos) << part << " not in:\n" << t;
}
