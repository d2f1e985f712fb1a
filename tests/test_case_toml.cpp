// Tests of input/case_toml: a valid case parses; every bad input stops with a message naming the
// key, the value and the allowed range.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "solver/state.hpp"
#include "solver/summary.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << "test setup: '" << from << "' not in the case";
  if (pos != std::string::npos) s.replace(pos, from.size(), to);
  return s;
}

// Parses `text` (with overrides) and returns the InputError message ("" if none was raised).
std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_case(text, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

struct BadInput {
  const char* name;
  std::string from, to;     // text replacement in the strip case
  std::string set;          // or a --set override
  std::vector<std::string> expect;  // substrings the message must contain
};

}  // namespace

TEST(CaseToml, valid_case_parses_with_derived_fields) {
  const Case c = parse_case(test::strip_case_toml());
  ASSERT_EQ(c.materials.size(), 1u);
  EXPECT_DOUBLE_EQ(c.materials[0].youngs_modulus, 5.2e9);
  ASSERT_EQ(c.bodies.size(), 1u);
  EXPECT_EQ(c.bodies[0].field, 0);
  EXPECT_EQ(c.solver.scheme, Scheme::MUSL);
  ASSERT_EQ(c.boundary.size(), 1u);
  EXPECT_EQ(c.boundary[0].edge, Edge::left);
  EXPECT_DOUBLE_EQ(c.boundary[0].from, 0.0);  // defaults to the whole edge
  EXPECT_DOUBLE_EQ(c.boundary[0].to, 0.002);
  EXPECT_NE(c.input_toml.find("homalite"), std::string::npos);
}

TEST(CaseToml, set_overrides_values_and_is_validated_the_same_way) {
  const Case c = parse_case(test::strip_case_toml(),
                            {"boundary.push.velocity=30", "solver.scheme=USL", "time.cfl = 0.2"});
  EXPECT_DOUBLE_EQ(c.boundary[0].velocity.value, 30.0);
  EXPECT_EQ(c.solver.scheme, Scheme::USL);
  EXPECT_DOUBLE_EQ(c.time.cfl, 0.2);
  const std::string e = error_of(test::strip_case_toml(), {"grid.cell_size=-1"});
  EXPECT_NE(e.find("grid.cell_size"), std::string::npos) << e;
  EXPECT_NE(e.find("> 0"), std::string::npos) << e;
}

TEST(CaseToml, every_bad_input_is_reported_with_key_value_and_rule) {
  const std::vector<BadInput> cases = {
      {"unknown top-level key", "title =", "titel =", "", {"'titel'", "unknown key"}},
      {"unknown key (typo)", "cell_size = 0.5e-3", "cel_size = 0.5e-3", "", {"grid.cel_size", "unknown key"}},
      {"wrong type", "cell_size = 0.5e-3", "cell_size = \"fine\"", "", {"grid.cell_size", "\"fine\"", "must be a number"}},
      {"negative cell size", "cell_size = 0.5e-3", "cell_size = -0.5e-3", "", {"grid.cell_size", "-0.0005", "> 0"}},
      {"zero cell size", "cell_size = 0.5e-3", "cell_size = 0.0", "", {"grid.cell_size", "= 0", "> 0"}},
      {"cell size not dividing domain", "cell_size = 0.5e-3", "cell_size = 0.3e-3", "", {"grid.cell_size", "whole cells"}},
      {"poisson ratio 0.5", "poisson_ratio = 0.34", "poisson_ratio = 0.5", "", {"materials.homalite.poisson_ratio", "0.5", "(-1, 0.5)"}},
      {"poisson ratio below -1", "poisson_ratio = 0.34", "poisson_ratio = -1.2", "", {"poisson_ratio", "-1.2", "(-1, 0.5)"}},
      {"negative modulus", "youngs_modulus = 5.2e9", "youngs_modulus = -5.2e9", "", {"youngs_modulus", "> 0"}},
      {"zero density", "density = 1246.0", "density = 0.0", "", {"materials.homalite.density", "> 0"}},
      {"cfl zero", "cfl = 0.4", "cfl = 0.0", "", {"time.cfl", "(0, 1]"}},
      {"cfl above one", "cfl = 0.4", "cfl = 1.5", "", {"time.cfl", "1.5", "(0, 1]"}},
      {"negative end time", "end = 2e-6", "end = -2e-6", "", {"time.end", "> 0"}},
      {"body outside grid", "max = [0.01, 0.002]\n[time]", "max = [0.02, 0.002]\n[time]", "", {"bodies.strip.max", "inside the grid"}},
      {"empty body", "min = [0.0, 0.0]\nmax = [0.01, 0.002]\n[time]", "min = [0.0, 0.002]\nmax = [0.01, 0.002]\n[time]", "", {"bodies.strip.max", "empty"}},
      {"unknown material", "material = \"homalite\"", "material = \"steel\"", "", {"bodies.strip.material", "\"steel\"", "homalite"}},
      {"bc range off the edge", "component = \"x\"", "component = \"x\"\nfrom = 0.001\nto = 0.005", "", {"boundary.push.to", "0.005", "left edge"}},
      {"bc edge name", "edge = \"left\"", "edge = \"front\"", "", {"boundary.push.edge", "\"front\"", "\"left\""}},
      {"bc component", "component = \"x\"", "component = \"z\"", "", {"boundary.push.component", "\"z\"", "\"x\", \"y\""}},
      {"bc unknown body", "component = \"x\"", "component = \"x\"\nbodies = [\"plate\"]", "", {"boundary.push.bodies", "\"plate\"", "strip"}},
      {"time key for constant", "velocity = 1.0", "velocity = 1.0\nrise_time = 1e-7", "", {"boundary.push.rise_time", "trapezoid"}},
      {"flip out of range", "flip = 1.0", "flip = 2.0", "", {"solver.flip", "2", "[0, 1]"}},
      {"scheme name", "scheme = \"MUSL\"", "scheme = \"FLIP\"", "", {"solver.scheme", "\"FLIP\"", "\"MUSL\""}},
      {"particles per cell", "particles_per_cell = 2", "particles_per_cell = 0", "", {"grid.particles_per_cell", "[1, 8]"}},
      {"missing table", "[time]\nend = 2e-6\ncfl = 0.4\n", "", "", {"time", "required"}},
      {"grid max below min", "max = [0.01, 0.002]\ncell_size", "max = [-0.01, 0.002]\ncell_size", "", {"grid.max", "must exceed"}},
      {"bad --set form", "", "", "grid.cell_size", {"--set", "dotted.key=value"}},
      {"--set into a value", "", "", "grid.cell_size.x=1", {"grid.cell_size", "non-table"}},
      {"negative margin", "", "", "grid.margin=-1e-3", {"grid.margin", "-0.001", "[0, half"}},
      {"follow_edge on a tangential bc", "component = \"x\"", "component = \"y\"\nfollow_edge = true", "", {"boundary.push.follow_edge", "normal to the left edge"}},
      {"follow_edge not a bool", "component = \"x\"", "component = \"x\"\nfollow_edge = 1", "", {"boundary.push.follow_edge", "true or false"}},
      {"stop flag not a bool", "cfl = 0.4", "cfl = 0.4\nstop_at_interface_end = \"yes\"", "", {"time.stop_at_interface_end", "true or false"}},
      {"absorbing edge also driven", "[output]", "[absorbing]\nedges = [\"left\"]\n[output]", "", {"absorbing.edges", "\"left\"", "boundary.push", "cannot also"}},
      {"absorbing edge name", "[output]", "[absorbing]\nedges = [\"front\"]\n[output]", "", {"absorbing.edges", "\"front\"", "\"right\""}},
      {"negative snapshot interval", "history_interval = 0.1e-6", "history_interval = 0.1e-6\nsnapshot_interval = -1.0", "", {"output.snapshot_interval", ">= 0"}},
  };
  EXPECT_GE(cases.size(), 15u);
  for (const BadInput& b : cases) {
    std::string text = test::strip_case_toml();
    if (!b.from.empty()) text = replace(text, b.from, b.to);
    std::vector<std::string> overrides;
    if (!b.set.empty()) overrides.push_back(b.set);
    const std::string msg = error_of(text, overrides);
    EXPECT_FALSE(msg.empty()) << b.name << ": no error raised";
    for (const std::string& s : b.expect)
      EXPECT_NE(msg.find(s), std::string::npos) << b.name << ": '" << s << "' not in: " << msg;
  }
}

// Free surfaces need room to move outward: the ghost margin defaults to the largest prescribed
// displacement over the run (here 1 m/s for 2 us = 2 um: 1 extra cell of 0.5 mm), or is given.
TEST(CaseToml, ghost_margin_covers_the_prescribed_displacement) {
  const Case c = parse_case(test::strip_case_toml(), {"boundary.push.velocity=-300"});
  EXPECT_NEAR(c.grid.margin, 300.0 * 2e-6, 1e-12);  // 0.6 mm
  const Grid g = build_grid(c.grid);
  EXPECT_EQ(g.ghost, 2 + 2);                         // ceil(0.6 / 0.5) more cells
  EXPECT_NEAR(g.x.node(0), -4 * 0.5e-3, 1e-15);
  EXPECT_EQ(g.physical_cells_x(), 20);
  const Case given = parse_case(test::strip_case_toml(), {"grid.margin=0"});
  EXPECT_EQ(build_grid(given.grid).ghost, 2);
  // A long run at constant velocity: the automatic margin stops at half the larger extent.
  const Case capped = parse_case(test::strip_case_toml(), {"time.end=10.0"});
  EXPECT_NEAR(capped.grid.margin, 0.005, 1e-15);
}

TEST(CaseToml, syntax_error_gives_line_and_column) {
  const std::string msg = error_of("[grid\ncell_size = 1");
  EXPECT_NE(msg.find("TOML syntax error"), std::string::npos) << msg;
  EXPECT_NE(msg.find(":1:"), std::string::npos) << msg;
}

TEST(CaseToml, overlapping_bodies_are_rejected) {
  std::string text = test::strip_case_toml();
  text = replace(text, "[time]", "[bodies.other]\nmaterial = \"homalite\"\nmin = [0.005, 0.0]\nmax = [0.01, 0.001]\n[time]");
  const std::string msg = error_of(text);
  EXPECT_NE(msg.find("overlaps"), std::string::npos) << msg;
}

namespace {

// The strip case with one more [boundary.NAME] table on `edge` (extra lines appended).
std::string with_condition(const std::string& name, const std::string& lines) {
  return replace(test::strip_case_toml(), "[output]", "[boundary." + name + "]\n" + lines + "\n[output]");
}

bool any_warning_has(const Case& c, const std::string& text) {
  for (const std::string& w : c.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(CaseToml, conflicting_velocity_conditions_on_shared_nodes_are_rejected) {
  // boundary.push: v_x = 1 on the whole left edge (y in [0, 2] mm), nodes every 0.5 mm.
  const std::string msg = error_of(with_condition("pull", "edge = \"left\"\ncomponent = \"x\"\nfrom = 0.001\nvelocity = -2.0"));
  for (const char* s : {"'boundary.push'", "'boundary.pull'", "v_x on the left edge", "y in [0.001, 0.002] m",
                        "boundary.push: velocity = 1 (constant)", "boundary.pull: velocity = -2 (constant)",
                        "disjoint"})
    EXPECT_NE(msg.find(s), std::string::npos) << "missing '" << s << "' in: " << msg;
  // Same value, other time function: still two values on one node.
  EXPECT_NE(error_of(with_condition("ramp", "edge = \"left\"\ncomponent = \"x\"\nfunction = \"trapezoid\"\n"
                                            "velocity = 1.0\nrise_time = 1e-7\nplateau_time = 1e-6\nfall_time = 1e-7"))
                .find("trapezoid: rise_time = 1e-07"),
            std::string::npos);
  // Ranges meeting on a node (y = 1 mm) share it ...
  const std::string push_low = "boundary.push.to=0.001";
  EXPECT_NE(error_of(with_condition("pull", "edge = \"left\"\ncomponent = \"x\"\nfrom = 0.001\nvelocity = -2.0"), {push_low}),
            "");
  // ... between nodes they do not; nor do other components, edges or disjoint ranges.
  EXPECT_EQ(error_of(with_condition("pull", "edge = \"left\"\ncomponent = \"x\"\nfrom = 0.00125\nvelocity = -2.0"),
                     {"boundary.push.to=0.00125"}), "");
  EXPECT_EQ(error_of(with_condition("slide", "edge = \"left\"\ncomponent = \"y\"\nvelocity = -2.0")), "");
  EXPECT_EQ(error_of(with_condition("pull", "edge = \"right\"\ncomponent = \"x\"\nvelocity = -2.0")), "");
}

TEST(CaseToml, identical_conditions_on_shared_nodes_are_redundant_not_wrong) {
  const Case c = parse_case(with_condition("again", "edge = \"left\"\ncomponent = \"x\"\nto = 0.001\nvelocity = 1.0"));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("boundary.push and boundary.again"), std::string::npos) << c.warnings[0];
  EXPECT_NE(c.warnings[0].find("redundant"), std::string::npos) << c.warnings[0];
}

TEST(CaseToml, touching_bodies_without_an_interface_are_an_error) {
  EXPECT_TRUE(parse_case(test::strip_case_toml()).warnings.empty());
  // The strip cut in two at x = 5 mm: two velocity fields meeting along x = 0.005, y in [0, 2] mm.
  std::vector<std::string> cut = {"bodies.strip.max=[0.005, 0.002]", "bodies.right.material=homalite",
                                  "bodies.right.min=[0.005, 0.0]", "bodies.right.max=[0.01, 0.002]"};
  const std::string e = error_of(test::strip_case_toml(), cut);
  for (const char* s : {"bodies.strip and bodies.right", "x = 0.005 m, y in [0, 0.002] m", "no [interface]",
                        "pass through each other", "law = \"contact\""})
    EXPECT_NE(e.find(s), std::string::npos) << "missing '" << s << "' in: " << e;
  // Asking for contact (an interface of law "contact" along their common edge) makes it valid.
  for (const char* k : {"interface.touch.upper_body=strip", "interface.touch.lower_body=right",
                        "interface.touch.points=[[0.005, 0.0], [0.005, 0.002]]", "interface.touch.segments=8",
                        "interface.touch.law=contact", "interface.touch.contact_stiffness=1e14"})
    cut.push_back(k);
  const Case c = parse_case(test::strip_case_toml(), cut);
  EXPECT_TRUE(c.warnings.empty()) << c.warnings.front();
  EXPECT_TRUE(c.interfaces.at(0).precracked && c.interfaces.at(0).contact);
  // Meeting at a corner only, or apart: nothing to say.
  const Case corner = parse_case(test::strip_case_toml(),
                                 {"bodies.strip.max=[0.005, 0.001]", "bodies.right.material=homalite",
                                  "bodies.right.min=[0.005, 0.001]", "bodies.right.max=[0.01, 0.002]"});
  EXPECT_TRUE(corner.warnings.empty()) << corner.warnings.front();
  // The reference problem's halves touch along y = 0 but are joined by the weak plane (a
  // cohesive interface from the notch tip on, bonded beyond its end; the notch itself is the
  // pre-crack): no warning. Its upper body is the second field: the pair matches either way.
  const Case reference = load_case(std::string(RUPTURE_SOURCE_DIR) + "/examples/rosakis1999.toml");
  EXPECT_TRUE(reference.warnings.empty()) << reference.warnings.front();
}

TEST(CaseToml, a_run_of_more_than_ten_million_steps_is_warned_about) {
  // dt = 0.4 x 0.5 mm / c_D = 7.9e-8 s: 1 s is 1.27e7 steps, 0.5 s 6.3e6.
  EXPECT_TRUE(parse_case(test::strip_case_toml(), {"time.end=0.5"}).warnings.empty());
  const Case c = parse_case(test::strip_case_toml(), {"time.end=1.0"});
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_TRUE(any_warning_has(c, "12672353 time steps")) << c.warnings[0];
  EXPECT_TRUE(any_warning_has(c, "more than 1e7")) << c.warnings[0];
}

// --- Shapes, cut-outs, initial stress and velocity fields (docs/geometry.md) ---------------

namespace {

// The strip case with `bodies` (TOML) in place of its one body, and `extra` tables appended.
std::string with_bodies(const std::string& bodies, const std::string& extra = "") {
  return replace(test::strip_case_toml(),
                 "[bodies.strip]\nmaterial = \"homalite\"\nmin = [0.0, 0.0]\nmax = [0.01, 0.002]\n", bodies) +
         extra;
}

// A plate with a circular hole (r = 0.5 mm) and a notch, a triangle sharing its field, and an
// ellipse of its own field.
const char* kShapes = R"(
[bodies.plate]
material = "homalite"
min = [0.0, 0.0]
max = [0.006, 0.002]
stress = [1e6, -2e6, 3e5]
field = "solid"
[[bodies.plate.minus]]
shape = "circle"
center = [0.003, 0.001]
radius = 0.0005
[[bodies.plate.minus]]
min = [0.0, 0.00085]
max = [0.001, 0.00115]
[bodies.wedge]
material = "homalite"
shape = "polygon"
vertices = [[0.006, 0.0], [0.01, 0.0], [0.006, 0.002]]
field = "solid"
[bodies.disc]
material = "homalite"
shape = "ellipse"
center = [0.0085, 0.0015]
radii = [0.001, 0.0004]
angle = 10
)";

}  // namespace

TEST(CaseToml, shapes_cut_outs_stress_and_fields_parse) {
  // The ellipse as written grazes the wedge: another field, no interface, an error. Moved clear
  // of it, the case is valid.
  const std::string grazing = error_of(with_bodies(kShapes));
  EXPECT_NE(grazing.find("bodies.wedge and bodies.disc touch near ("), std::string::npos) << grazing;
  const Case c = parse_case(with_bodies(kShapes), {"bodies.disc.center=[0.0089, 0.0015]", "bodies.disc.radii=[0.0006, 0.0003]"});
  ASSERT_EQ(c.bodies.size(), 3u);
  ASSERT_EQ(c.field_names, (std::vector<std::string>{"solid", "disc"}));  // order of first appearance
  EXPECT_EQ(c.bodies[0].field, 0);
  EXPECT_EQ(c.bodies[1].field, 0);
  EXPECT_EQ(c.bodies[2].field, 1);
  const BodySpec& plate = c.bodies[0];
  EXPECT_EQ(plate.region.outer.kind, ShapeKind::rectangle);
  ASSERT_EQ(plate.region.minus.size(), 2u);
  EXPECT_EQ(plate.region.minus[0].kind, ShapeKind::circle);
  EXPECT_EQ(plate.region.minus[1].kind, ShapeKind::rectangle);
  EXPECT_FALSE(plate.plain_rectangle());
  EXPECT_DOUBLE_EQ(plate.stress[0], 1e6);
  EXPECT_DOUBLE_EQ(plate.stress[1], -2e6);
  EXPECT_DOUBLE_EQ(plate.stress[2], 3e5);
  EXPECT_EQ(c.bodies[1].region.outer.vertices.size(), 3u);
  EXPECT_DOUBLE_EQ(c.bodies[1].min[0], 0.006);  // the bounding box
  EXPECT_DOUBLE_EQ(c.bodies[1].max[1], 0.002);
  EXPECT_NEAR(c.bodies[2].region.outer.angle, 10 * 3.14159265358979 / 180, 1e-12);
  EXPECT_DOUBLE_EQ(c.bodies[2].region.outer.center[0], 0.0089);
  // The plate and the wedge are one continuum (touching is what they are for).
  EXPECT_TRUE(c.warnings.empty()) << c.warnings.front();
  // The state has one grid field per velocity field, and particles say which.
  const State s = make_state(c);
  EXPECT_EQ(s.fields.num_fields, 2);
  const CaseSummary sum = summarize(c);
  EXPECT_EQ(long(s.particles.size()), sum.particles) << "summary and seeding disagree";
  long in_hole = 0, in_notch = 0, disc = 0;
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    const double x = s.particles.x[p], y = s.particles.y[p];
    in_hole += std::hypot(x - 0.003, y - 0.001) < 0.0005;
    in_notch += x < 0.001 && y > 0.00085 && y < 0.00115;
    disc += s.particles.field[p] == 1;
  }
  EXPECT_EQ(in_hole, 0);
  EXPECT_EQ(in_notch, 0);
  EXPECT_EQ(disc, sum.particles_per_body[2]);
  // The plate: 24 x 8 sub-cells minus 12 in the hole (r = 2 sub-cells: the 12 centres within
  // 0.5 mm of a sub-cell corner) and 2 rows x 4 in the notch.
  EXPECT_EQ(sum.particles_per_body[0], 24 * 8 - 12 - 8);
}

TEST(CaseToml, bodies_sharing_a_field_map_to_it_in_boundaries_and_interfaces) {
  const std::string halves = R"(
[bodies.lower]
material = "homalite"
min = [0.0, 0.0]
max = [0.01, 0.001]
field = "plate"
[bodies.upper]
material = "homalite"
min = [0.0, 0.001]
max = [0.01, 0.002]
field = "plate"
)";
  const Case c = parse_case(with_bodies(halves), {"boundary.push.bodies=[\"upper\", \"lower\"]"});
  EXPECT_EQ(c.field_names, (std::vector<std::string>{"plate"}));
  ASSERT_EQ(c.boundary[0].fields, (std::vector<int>{0}));  // one field, named twice
  EXPECT_TRUE(c.warnings.empty()) << "one continuum touching itself: " << c.warnings.front();
  const std::string weak = R"(
[interface.weak]
upper_body = "upper"
lower_body = "lower"
y = 0.001
start = 0.002
end = 0.008
segments = 12
sigma_max = 24e6
delta_n = 0.4e-6
)";
  const std::string e = error_of(with_bodies(halves, weak));
  for (const char* s : {"interface.weak.lower_body", "\"lower\"", "bodies.upper and bodies.lower",
                        "share the velocity field \"plate\"", "two different fields"})
    EXPECT_NE(e.find(s), std::string::npos) << "missing '" << s << "' in: " << e;
  // Own fields (the default): the interface joins them.
  std::string own = with_bodies(halves, weak);
  while (own.find("field = \"plate\"\n") != std::string::npos) own = replace(own, "field = \"plate\"\n", "");
  const Case joined = parse_case(own);
  ASSERT_EQ(joined.interfaces.size(), 1u);
  EXPECT_EQ(joined.interfaces[0].upper_field, 1);
  EXPECT_EQ(joined.interfaces[0].lower_field, 0);
  EXPECT_EQ(joined.interfaces[0].upper_body, 1);
  EXPECT_TRUE(joined.warnings.empty()) << joined.warnings.front();
}

TEST(CaseToml, touching_shapes_of_different_fields_are_an_error) {
  // An inclusion filling a plate's hole: touching all around, another field, no interface.
  const std::string inclusion = R"(
[bodies.plate]
material = "homalite"
min = [0.0, 0.0]
max = [0.01, 0.002]
[[bodies.plate.minus]]
shape = "circle"
center = [0.005, 0.001]
radius = 0.0007
[bodies.inclusion]
material = "homalite"
shape = "circle"
center = [0.005, 0.001]
radius = 0.0007
)";
  const std::string touching = error_of(with_bodies(inclusion));
  for (const char* s : {"bodies.plate and bodies.inclusion touch near (", "no [interface] joins them",
                        "pass through each other", "same bodies.NAME.field"})
    EXPECT_NE(touching.find(s), std::string::npos) << "missing '" << s << "' in: " << touching;
  // One field: one continuum, nothing to say. Apart: nothing either.
  EXPECT_TRUE(parse_case(with_bodies(inclusion), {"bodies.inclusion.field=plate"}).warnings.empty());
  EXPECT_TRUE(parse_case(with_bodies(inclusion), {"bodies.inclusion.radius=0.0004"}).warnings.empty());
  // Larger than the hole: they overlap.
  const std::string e = error_of(with_bodies(inclusion), {"bodies.inclusion.radius=0.0009"});
  EXPECT_NE(e.find("'bodies.inclusion'"), std::string::npos) << e;
  EXPECT_NE(e.find("overlaps bodies.plate"), std::string::npos) << e;
}

TEST(CaseToml, every_bad_shape_is_reported_with_key_value_and_rule) {
  struct BadBody {
    const char* name;
    std::string body;                 // the [bodies.strip] table's keys after material
    std::vector<std::string> expect;  // substrings the message must contain
  };
  const std::vector<BadBody> cases = {
      {"bow-tie polygon", "shape = \"polygon\"\nvertices = [[0.0, 0.0], [0.004, 0.002], [0.004, 0.0], [0.0, 0.002]]",
       {"bodies.strip.vertices", "intersects itself", "edge 0 from (0, 0) to (0.004, 0.002)",
        "edge 2 from (0.004, 0) to (0, 0.002)"}},
      {"repeated vertex", "shape = \"polygon\"\nvertices = [[0.0, 0.0], [0.004, 0.0], [0.004, 0.002], [0.0, 0.0]]",
       {"bodies.strip.vertices", "vertices 0 and 3 are the same point (0, 0)"}},
      {"collinear polygon", "shape = \"polygon\"\nvertices = [[0.0, 0.0], [0.002, 0.001], [0.004, 0.002]]",
       {"bodies.strip.vertices", "no area"}},
      {"two vertices", "shape = \"polygon\"\nvertices = [[0.0, 0.0], [0.002, 0.001]]",
       {"bodies.strip.vertices", "at least 3 points"}},
      {"bad vertex", "shape = \"polygon\"\nvertices = [[0.0, 0.0], [0.002], [0.004, 0.002]]",
       {"bodies.strip.vertices", "vertex 1 is [ 0.002 ]", "two finite numbers"}},
      {"zero radius", "shape = \"circle\"\ncenter = [0.005, 0.001]\nradius = 0.0", {"bodies.strip.radius", "= 0:", "> 0"}},
      {"negative radius", "shape = \"circle\"\ncenter = [0.005, 0.001]\nradius = -0.001",
       {"bodies.strip.radius", "-0.001", "> 0"}},
      {"missing center", "shape = \"circle\"\nradius = 0.001", {"bodies.strip.center", "(missing)"}},
      {"ellipse radius zero", "shape = \"ellipse\"\ncenter = [0.005, 0.001]\nradii = [0.002, 0.0]",
       {"bodies.strip.radii", "[0.002, 0]", "both semi-axes"}},
      {"ellipse radii missing", "shape = \"ellipse\"\ncenter = [0.005, 0.001]", {"bodies.strip.radii", "(missing)"}},
      {"key of another shape", "shape = \"circle\"\ncenter = [0.005, 0.001]\nradius = 0.0005\nradii = [1.0, 1.0]",
       {"bodies.strip.radii", "not a key of shape = \"circle\"", "\"center\", \"radius\"", "ellipse"}},
      {"rectangle keys on a polygon", "shape = \"polygon\"\nvertices = [[0.0, 0.0], [0.004, 0.0], [0.0, 0.002]]\nmin = [0.0, 0.0]",
       {"bodies.strip.min", "not a key of shape = \"polygon\""}},
      {"unknown shape", "shape = \"square\"\nmin = [0.0, 0.0]\nmax = [0.01, 0.002]",
       {"bodies.strip.shape", "\"square\"", "\"polygon\""}},
      {"circle off the grid", "shape = \"circle\"\ncenter = [0.0095, 0.001]\nradius = 0.0008",
       {"bodies.strip.center", "circle spanning [0.0087, 0.0002]..[0.0103, 0.0018]", "inside the grid"}},
      {"no particle", "shape = \"circle\"\ncenter = [0.001, 0.001]\nradius = 0.00001",
       {"'bodies.strip' = \"strip\"", "holds no particle"}},
      {"hole outside the body",
       "min = [0.0, 0.0]\nmax = [0.005, 0.002]\n[[bodies.strip.minus]]\nshape = \"circle\"\ncenter = [0.008, 0.001]\nradius = 0.0005",
       {"bodies.strip.minus[0].shape", "\"circle\" spanning", "outside the body", "[0, 0]..[0.005, 0.002]"}},
      {"hole between particles",
       "min = [0.0, 0.0]\nmax = [0.01, 0.002]\n[[bodies.strip.minus]]\nshape = \"circle\"\ncenter = [0.005, 0.001]\nradius = 0.00005",
       {"bodies.strip.minus[0]", "removes no particle"}},
      {"notch thinner than a particle row",
       "min = [0.0, 0.0]\nmax = [0.01, 0.002]\n[[bodies.strip.minus]]\nmin = [0.0, 0.0009]\nmax = [0.002, 0.0011]",
       {"bodies.strip.minus[0]", "\"rectangle\" spanning [0, 0.0009]..[0.002, 0.0011]", "removes no particle"}},
      {"empty cut-out", "min = [0.0, 0.0]\nmax = [0.01, 0.002]\n[[bodies.strip.minus]]\nmin = [0.001, 0.001]\nmax = [0.001, 0.002]",
       {"bodies.strip.minus[0].max", "the cut-out is empty"}},
      {"minus not tables", "min = [0.0, 0.0]\nmax = [0.01, 0.002]\nminus = 1", {"bodies.strip.minus", "array of tables"}},
      {"unknown key in a cut-out",
       "min = [0.0, 0.0]\nmax = [0.01, 0.002]\n[[bodies.strip.minus]]\nshape = \"circle\"\ncentre = [0.005, 0.001]\nradius = 0.0005",
       {"bodies.strip.minus[0].centre", "unknown key", "did you mean 'bodies.strip.minus[0].center'"}},
      {"stress of two numbers", "min = [0.0, 0.0]\nmax = [0.01, 0.002]\nstress = [1e6, 2e6]",
       {"bodies.strip.stress", "three finite numbers [sxx, syy, sxy] (Pa)"}},
      {"empty field name", "min = [0.0, 0.0]\nmax = [0.01, 0.002]\nfield = \"\"", {"bodies.strip.field", "velocity field"}},
      {"field not a string", "min = [0.0, 0.0]\nmax = [0.01, 0.002]\nfield = 3", {"bodies.strip.field", "must be a string"}},
  };
  for (const BadBody& b : cases) {
    const std::string msg = error_of(with_bodies("[bodies.strip]\nmaterial = \"homalite\"\n" + b.body + "\n"));
    EXPECT_FALSE(msg.empty()) << b.name << ": no error raised";
    for (const std::string& s : b.expect)
      EXPECT_NE(msg.find(s), std::string::npos) << b.name << ": '" << s << "' not in: " << msg;
  }
}

// Materials as seismologists give them, (c_P, c_S, rho): mu = rho c_S^2, lambda + 2 mu = rho c_P^2.
// Round trip through the independent wave-speed formulas of material/elastic: Homalite's (E, nu)
// -> its plane-strain c_D, c_S -> a material given by those speeds -> the same E and nu, and the
// same speeds back. The speeds are the 3D ones, so under plane stress E and nu are the same and
// the printed c_D is the plate's, sqrt(E / (rho (1 - nu^2))).
TEST(CaseToml, materials_from_wave_speeds_round_trip) {
  const ElasticMaterial homalite{"homalite", 5.2e9, 0.34, 1246.0};
  const WaveSpeeds w = wave_speeds(homalite, PlaneMode::strain);
  const std::string speeds = fmt::format("p_wave_speed = {:.17g}\ns_wave_speed = {:.17g}\ndensity = 1246.0",
                                         w.dilatational, w.shear);
  const std::string text = replace(test::strip_case_toml(), "youngs_modulus = 5.2e9\npoisson_ratio = 0.34\ndensity = 1246.0", speeds);
  for (const PlaneMode mode : {PlaneMode::strain, PlaneMode::stress}) {
    const Case c = parse_case(text, {mode == PlaneMode::strain ? "model.plane=\"strain\"" : "model.plane=\"stress\""});
    const ElasticMaterial& m = c.materials.at(0);
    EXPECT_NEAR(m.youngs_modulus, 5.2e9, 1e-12 * 5.2e9);
    EXPECT_NEAR(m.poisson_ratio, 0.34, 1e-12);
    const WaveSpeeds back = wave_speeds(m, mode);
    EXPECT_NEAR(back.shear, w.shear, 1e-12 * w.shear);
    const double cd = mode == PlaneMode::strain ? w.dilatational
                                                : std::sqrt(5.2e9 / (1246.0 * (1.0 - 0.34 * 0.34)));
    EXPECT_NEAR(back.dilatational, cd, 1e-12 * cd);
  }
  // A Poisson solid (c_P = sqrt 3 c_S): nu = 1/4, E = 2.5 mu.
  const Case p = parse_case(replace(test::strip_case_toml(), "youngs_modulus = 5.2e9\npoisson_ratio = 0.34\ndensity = 1246.0",
                                    "p_wave_speed = 6000.0\ns_wave_speed = 3464.1016151377544\ndensity = 2670.0"));
  EXPECT_NEAR(p.materials[0].poisson_ratio, 0.25, 1e-12);
  EXPECT_NEAR(p.materials[0].youngs_modulus, 2.5 * 2670.0 * 12e6, 1e-9 * 2.5 * 2670.0 * 12e6);
  // One pair or the other, and a positive bulk modulus.
  const std::string both = replace(test::strip_case_toml(), "density = 1246.0", "density = 1246.0\np_wave_speed = 2500.0\ns_wave_speed = 1300.0");
  const std::string mixed = error_of(both);
  EXPECT_NE(mixed.find("'materials.homalite.youngs_modulus' = 5200000000"), std::string::npos) << mixed;
  EXPECT_NE(mixed.find("not with p_wave_speed and s_wave_speed"), std::string::npos) << mixed;
  const std::string slow = error_of(replace(test::strip_case_toml(), "youngs_modulus = 5.2e9\npoisson_ratio = 0.34",
                                            "p_wave_speed = 1400.0\ns_wave_speed = 1300.0"));
  EXPECT_NE(slow.find("'materials.homalite.p_wave_speed' = 1400"), std::string::npos) << slow;
  EXPECT_NE(slow.find("must exceed 2/sqrt(3) s_wave_speed = 1501.1"), std::string::npos) << slow;
  const std::string alone = error_of(replace(test::strip_case_toml(), "youngs_modulus = 5.2e9\npoisson_ratio = 0.34",
                                             "p_wave_speed = 2500.0"));
  EXPECT_NE(alone.find("s_wave_speed"), std::string::npos) << alone;
}
