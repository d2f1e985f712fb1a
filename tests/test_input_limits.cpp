// Tests of input/names and input/text_limits: every name a user gives is checked against one rule
// (no name can reach a path outside the run directory), and no text can exhaust the parser's
// stack or the memory before it is parsed.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "input/names.hpp"
#include "input/text_limits.hpp"
#include "solver/summary.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_case(text, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) s.replace(pos, from.size(), to);
  return s;
}

}  // namespace

TEST(Names, rule_accepts_letters_digits_underscore_and_hyphen_only) {
  EXPECT_TRUE(valid_name("weak_plane"));
  EXPECT_TRUE(valid_name("st-12"));
  EXPECT_TRUE(valid_name(std::string(kMaxNameLength, 'a')));
  EXPECT_FALSE(valid_name(""));
  EXPECT_FALSE(valid_name(std::string(kMaxNameLength + 1, 'a')));
  for (const char* bad : {"..", "a/b", "../../../names/evil", "a b", "a.b", "a\\b", "é"})
    EXPECT_FALSE(valid_name(bad)) << bad;
  EXPECT_FALSE(valid_name(std::string("a\0b", 3)));
}

TEST(Names, printable_escapes_control_bytes_so_a_nul_does_not_cut_a_message) {
  EXPECT_EQ(printable(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(printable("say \"hi\""), "say \\x22hi\\x22");
  EXPECT_EQ(printable(std::string(500, 'x')).size(), 203u);  // 200 then "..."
}

// Every kind of named entry: the message names the entry, shows the name and states the rule.
TEST(Names, every_named_table_checks_its_names) {
  const std::string base = test::strip_case_toml();
  struct Case_ {
    std::string from, to, key;
  };
  const std::vector<Case_> cases = {
      {"[materials.homalite]", "[materials.\"a/b\"]", "materials.a/b"},
      {"[bodies.strip]", "[bodies.\"../../../names/evil\"]", "bodies.../../../names/evil"},
      {"[boundary.push]", "[boundary.\"x y\"]", "boundary.x y"},
      {"[output]", "[interface.\"a/b\"]\nfrom = [0.0, 0.001]\nto = [0.01, 0.001]\n[output]", "interface.a/b"},
      {"[output]", "[stations.\"x/y\"]\nat = [0.005, 0.001]\n[output]", "stations.x/y"},
      {"[output]", "[loads.\"..\"]\ntype = \"body_force\"\ngravity = [0.0, -9.8]\n[output]", "loads..."},
  };
  for (const Case_& k : cases) {
    const std::string e = error_of(replaced(base, k.from, k.to));
    EXPECT_NE(e.find("input key '" + k.key + "'"), std::string::npos) << e;
    EXPECT_NE(e.find("1 to 64 characters from A-Z a-z 0-9 _ -"), std::string::npos) << e;
  }
  const std::string long_name(300, 'n');
  const std::string e = error_of(replaced(base, "[bodies.strip]", "[bodies." + long_name + "]"));
  EXPECT_NE(e.find("is 300 characters long"), std::string::npos) << e;
  const std::string f = error_of(base, {"bodies.strip.field=a/b"});
  EXPECT_NE(f.find("input key 'bodies.strip.field' = \"a/b\": the name holds '/'"), std::string::npos) << f;
  const std::string nul = error_of(replaced(base, "[bodies.strip]", "[bodies.\"a\\u0000b\"]"));
  EXPECT_NE(nul.find("\"a\\x00b\": the name holds '\\x00'"), std::string::npos) << nul;
}

TEST(Names, an_empty_material_name_is_shown_as_empty_not_missing) {
  const std::string e = error_of(test::strip_case_toml(), {"bodies.strip.material=\"\""});
  EXPECT_NE(e.find("'bodies.strip.material' = \"\": required"), std::string::npos) << e;
}

TEST(TextLimits, deep_dotted_headers_and_nesting_are_refused_before_parsing) {
  std::string header = "[a";
  for (int k = 0; k < 50000; ++k) header += ".a";
  const std::string e = error_of(header + "]\n");
  EXPECT_NE(e.find("a key of more than 32 dotted parts"), std::string::npos) << e;
  const std::string deep = "x = " + std::string(1000, '[') + "1" + std::string(1000, ']') + "\n";
  EXPECT_NE(error_of(deep).find("nested more than 32 deep"), std::string::npos);
  const std::string inline_deep = "x = " + std::string(100, '{') + "\n";
  EXPECT_NE(error_of(inline_deep).find("nested more than 32 deep"), std::string::npos);
  std::string key = "a";
  for (int k = 0; k < 100; ++k) key += ".a";
  EXPECT_NE(error_of(test::strip_case_toml(), {key + "=1"}).find("at most 32 parts"), std::string::npos);
  EXPECT_NE(error_of(test::strip_case_toml(), {"x=" + std::string(100, '[')}).find("nested more than 32"),
            std::string::npos);
}

// The scan counts the dots of keys only: values with many dots (numbers in a long array,
// strings, comments, multi-line strings) and a 32-part key are fine.
TEST(TextLimits, dots_and_brackets_of_values_strings_and_comments_do_not_count) {
  std::string text = "x = [";
  for (int k = 0; k < 1000; ++k) text += "1.5, ";
  text += "2.5]\n";
  text += "s = \"a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p.q.r.s.t.u.v.w.x.y.z.a.b.c.d.e.f.g.h [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[\"\n";
  text += "m = '''\n" + std::string(100, '.') + std::string(100, '[') + "\n'''\n";
  text += "e = \"\"\"quote \\\" inside\"\"\"\n";
  text += "# comment " + std::string(100, '.') + std::string(100, '{') + "\n";
  std::string key = "k";
  for (int k = 1; k < kMaxKeyParts; ++k) key += ".k";
  text += key + " = 1\n";
  EXPECT_NO_THROW(check_toml_limits(text, "t"));
  EXPECT_THROW(check_toml_limits(key + ".k = 1\n", "t"), InputError);
}

TEST(TextLimits, only_regular_files_of_bounded_size_are_read) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rupture_limits_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string file = (dir / "case.toml").string();
  std::ofstream(file) << "x = 1\n";
  EXPECT_EQ(read_bounded_file(file, 100, "case file"), "x = 1\n");
  try {
    read_bounded_file(file, 3, "case file");
    ADD_FAILURE() << "a file over the bound was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds 6 bytes"), std::string::npos) << e.what();
  }
  const std::string fifo = (dir / "fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(read_bounded_file(fifo, 100, "case file"), InputError);  // no hang: never opened
  EXPECT_THROW(read_bounded_file("/dev/urandom", 100, "case file"), InputError);
  EXPECT_THROW(read_bounded_file(dir.string(), 100, "case file"), InputError);
  EXPECT_THROW(read_bounded_file((dir / "missing").string(), 100, "case file"), InputError);
  fs::remove_all(dir);
}

// Finite but absurd inputs (input/case_checks check_run_limits): refused at input, naming the key,
// before any allocation or step.
TEST(RunLimits, absurd_materials_times_and_sizes_are_refused_before_any_work) {
  const std::string base = test::strip_case_toml();
  const std::string rho = error_of(base, {"materials.homalite.density=1e-300"});
  EXPECT_NE(rho.find("'materials.homalite'"), std::string::npos) << rho;
  EXPECT_NE(rho.find("c_D = inf m/s"), std::string::npos) << rho;
  const std::string stiff = error_of(base, {"materials.homalite.youngs_modulus=1e308"});
  EXPECT_NE(stiff.find("'time.end'"), std::string::npos) << stiff;
  EXPECT_NE(stiff.find("at most 4.504e+09"), std::string::npos) << stiff;
  const std::string end = error_of(base, {"time.end=1e308"});
  EXPECT_NE(end.find("'time.end' = 1e+308"), std::string::npos) << end;
  EXPECT_NE(end.find("inf steps"), std::string::npos) << end;
  // 3.8e9 steps of the strip (dt = 7.9e-8 s) are allowed, 5.1e9 are not: the bound is 2^52 x 1e-6.
  EXPECT_EQ(error_of(base, {"time.end=300.0"}), "");
  EXPECT_NE(error_of(base, {"time.end=400.0"}).find("at most 4.504e+09"), std::string::npos);
  // The strip's grid alone (at least 21 x 5 nodes, 11 doubles each: 0.009 MiB) fits in 0.02
  // MiB; with its 320 particles (122 bytes each) not, and that is known before any walk
  // (0.046 MiB); the whole case's estimate (every field's window, the sort's scratch: 0.062 MiB)
  // is above 0.05, where the walk-free bound fits.
  const std::string particles = error_of(base, {"solver.memory_limit_mib=0.02"});
  EXPECT_NE(particles.find("'solver.memory_limit_mib' = 0.02"), std::string::npos) << particles;
  EXPECT_NE(particles.find("the grid with its particles (exactly 320 particles, at least 105 nodes"),
            std::string::npos) << particles;
  EXPECT_NE(particles.find("needs about 0.046 MiB"), std::string::npos) << particles;
  const std::string memory = error_of(base, {"solver.memory_limit_mib=0.05"});
  EXPECT_NE(memory.find("'solver.memory_limit_mib' = 0.05"), std::string::npos) << memory;
  EXPECT_NE(memory.find("the case needs about 0.062 MiB"), std::string::npos) << memory;
  // Below the grid's own size the grid is refused first (check_grid_limits), before anything
  // counts particles.
  const std::string grid = error_of(base, {"solver.memory_limit_mib=0.001"});
  EXPECT_NE(grid.find("'solver.memory_limit_mib' = 0.001"), std::string::npos) << grid;
  EXPECT_NE(grid.find("the grid alone (at least 105 nodes"), std::string::npos) << grid;
  EXPECT_EQ(error_of(base, {"solver.memory_limit_mib=1000"}), "");
  EXPECT_NE(error_of(base, {"solver.memory_limit_mib=-1"}).find("must be >= 0"), std::string::npos);
}

// 80 000 x 16 000 cells at 2 x 2: 5.12e9 particles, past the 32-bit ids (refused before the
// memory check, which would refuse it too; the rectangle's count needs no walk, so the grid's
// early check refuses it).
TEST(RunLimits, particle_counts_past_32_bit_ids_are_refused) {
  const std::string e = error_of(test::strip_case_toml(), {"grid.cell_size=1.25e-7", "time.end=1e-9"});
  EXPECT_NE(e.find("'grid.cell_size' = 1.25e-07"), std::string::npos) << e;
  EXPECT_NE(e.find("the case seeds 5120000000 particles; at most 2^32 - 1"), std::string::npos) << e;
}

// A shaped body on a grid far beyond the memory: refused by the grid alone, at once, not after
// walking its 2e8 seed points (a disc of 40 mm in a 0.1 m square at 10 um cells, 2 x 2 per
// cell; 8400 MiB of grid against a limit of 1000).
TEST(RunLimits, a_shaped_body_on_an_absurd_grid_is_refused_by_the_grid_before_its_particles_are_counted) {
  const std::string disc = R"(
[model]
plane = "strain"
[materials.m]
youngs_modulus = 5.2e9
poisson_ratio = 0.34
density = 1246.0
[grid]
min = [0.0, 0.0]
max = [0.1, 0.1]
cell_size = 1e-5
[bodies.disc]
material = "m"
shape = "circle"
center = [0.05, 0.05]
radius = 0.04
[time]
end = 1e-9
)";
  const std::string e = error_of(disc, {"solver.memory_limit_mib=1000"});
  EXPECT_NE(e.find("'solver.memory_limit_mib' = 1000"), std::string::npos) << e;
  EXPECT_NE(e.find("the grid alone (at least 100020001 nodes"), std::string::npos) << e;
  // With room for the grid (8400 MiB) but not for the disc's 2.0e8 particles (at least
  // pi 0.04^2 / (5 um)^2 = 2.011e8 less the boundary strip's 1.2e5, 122 bytes each: 23 000 MiB more), refused
  // by the particles' walk-free bound, still before any walk (the walk took minutes).
  const std::string p = error_of(disc, {"solver.memory_limit_mib=9000"});
  EXPECT_NE(p.find("'solver.memory_limit_mib' = 9000"), std::string::npos) << p;
  EXPECT_NE(p.find("the grid with its particles (at least 2009"), std::string::npos) << p;
}

TEST(RunLimits, a_long_run_warns_with_its_count_beyond_what_a_long_holds) {
  const Case c = parse_case(test::strip_case_toml(), {"time.end=2.0"});  // 2.5e7 steps
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("more than 1e7"), std::string::npos) << c.warnings[0];
}

// What the nested set-up refuses, `rupture check` refuses too: at input, naming the key.
TEST(RunLimits, nested_levels_refuse_at_input_what_their_set_up_refuses) {
  const std::vector<std::string> nested = {
      "grid.cell_size=0.25e-3", "grid.coarse_cell_size=0.5e-3", "grid.refinement=\"nested\"",
      "grid.refine.f.min=[0.004,0.0]", "grid.refine.f.max=[0.006,0.002]", "grid.refine.f.level=1"};
  EXPECT_EQ(error_of(test::strip_case_toml(), nested), "");
  auto with = [&](const std::string& extra) {
    std::vector<std::string> o = nested;
    o.push_back(extra);
    return error_of(test::strip_case_toml(), o);
  };
  EXPECT_EQ(with("absorbing.edges=[\"right\"]"), "") << "[absorbing] on nested levels";
  const std::string loads = "loads.g={type=\"body_force\", acceleration=[0.0, -9.8]}";
  EXPECT_EQ(with(loads), "") << "[loads] on nested levels";
  std::vector<std::string> per_level = nested;
  per_level.push_back(loads);
  per_level.push_back("time.subcycling=\"levels\"");
  const std::string subcycled = error_of(test::strip_case_toml(), per_level);
  EXPECT_NE(subcycled.find("time.subcycling = \"levels\" with [loads] is not yet supported"), std::string::npos)
      << subcycled;
  per_level = nested;
  per_level.push_back("absorbing.edges=[\"right\"]");
  per_level.push_back("time.subcycling=\"levels\"");
  const std::string absorbing = error_of(test::strip_case_toml(), per_level);
  EXPECT_NE(absorbing.find("'grid.refinement' = \"nested\": time.subcycling = \"levels\" with [absorbing]"),
            std::string::npos)
      << absorbing;
}

// Messages the trial of issue 35 found wrong or missing.
TEST(InputMessages, refine_box_outside_the_grid_and_unresolvable_circle_are_named) {
  const std::string box = error_of(test::strip_case_toml(),
                                   {"grid.cell_size=0.25e-3", "grid.coarse_cell_size=0.5e-3", "grid.refine.f.min=[1.0,1.0]",
                                    "grid.refine.f.max=[1.001,1.001]", "grid.refine.f.level=1"});
  EXPECT_NE(box.find("'grid.refine.f.min'"), std::string::npos) << box;
  EXPECT_NE(box.find("the box lies outside the grid"), std::string::npos) << box;
  const std::vector<std::string> circle = {"interface.c.body=\"strip\"",  "interface.c.center=[0.005,0.001]",
                                           "interface.c.radius=1e-300",    "interface.c.segments=80",
                                           "interface.c.law=\"contact\"",  "interface.c.contact_stiffness=1e15"};
  const std::string tiny = error_of(test::strip_case_toml(), circle);
  EXPECT_NE(tiny.find("'interface.c.radius' = 1e-300"), std::string::npos) << tiny;
  EXPECT_NE(tiny.find("too small to resolve"), std::string::npos) << tiny;
}

// The nested levels' own set-up checks (a driven edge on every level's lines, an interface
// within one level) run at input too: rupture check --no-timing refuses what the run would.
TEST(RunLimits, nested_level_checks_of_interfaces_run_at_input) {
  const std::vector<std::string> nested = {
      "grid.cell_size=0.25e-3", "grid.coarse_cell_size=0.5e-3", "grid.refinement=\"nested\"",
      "grid.refine.f.min=[0.004,0.0]", "grid.refine.f.max=[0.006,0.002]", "grid.refine.f.level=1",
      "interface.c.body=\"strip\"", "interface.c.y=0.001", "interface.c.start=0.0", "interface.c.end=0.01",
      "interface.c.segments=40", "interface.c.law=\"contact\"", "interface.c.contact_stiffness=1e15"};
  const std::string e = error_of(test::strip_case_toml(), nested);
  EXPECT_NE(e.find("interface.c: its node at"), std::string::npos) << e;
  EXPECT_NE(e.find("not inside nested level"), std::string::npos) << e;
}

// A pre-crack inside one body may start on the edge of a hole cut out of it (docs/input.md:
// its ends may lie on the body's edge): straight lines from a 0.5 mm hole's edge to the
// strip's edge, along x, at 45 degrees and from just inside the material, are accepted.
TEST(InputMessages, a_crack_may_start_on_the_edge_of_a_hole) {
  for (const std::string from : {"[0.0055, 0.001]", "[0.00535355339059327, 0.00135355339059327]", "[0.00551, 0.001]"}) {
    const std::string to = from.find("0.00535") != std::string::npos ? "[0.006, 0.002]" : "[0.01, 0.001]";
    const std::string e = error_of(test::strip_case_toml(),
                                   {"bodies.strip.minus=[{shape=\"circle\", center=[0.005,0.001], radius=0.0005}]",
                                    "interface.c.body=\"strip\"", "interface.c.points=[" + from + "," + to + "]",
                                    "interface.c.segments=100", "interface.c.law=\"contact\"",
                                    "interface.c.contact_stiffness=1e15"});
    EXPECT_EQ(e, "") << from;
  }
}

// The walk-free estimate that refuses a case before its seed points are walked
// (solver/summary.hpp, memory_bytes_before_seeding) is never above the estimate `rupture check`
// prints, and equals it where every drawn body is a rectangle on grid lines, split by its
// cracks or not: so it refuses nothing the full estimate would let run.
TEST(RunLimits, the_estimate_before_seeding_is_at_most_the_full_one_and_exact_for_rectangles) {
  const std::string dir = std::string(RUPTURE_SOURCE_DIR) + "/examples/";
  int compared = 0, exact = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".toml") continue;
    const Case c = load_case(entry.path().string());
    if (c.grid.refined()) continue;
    const double before = memory_bytes_before_seeding(c), full = double(summarize(c).memory_bytes);
    bool rectangles = true;
    for (const BodySpec& b : c.bodies) rectangles = rectangles && b.region.outer.kind == ShapeKind::rectangle && b.region.minus.empty();
    EXPECT_LE(before, full) << entry.path().filename();
    if (rectangles) {
      EXPECT_EQ(before, full) << entry.path().filename();
      ++exact;
    }
    EXPECT_GT(before, 0.5 * full) << entry.path().filename() << ": the bound is loose";
    ++compared;
  }
  std::printf("%d examples on uniform grids compared, %d of them rectangles only\n", compared, exact);
  EXPECT_GE(compared, 20);
  EXPECT_GE(exact, 10);
}

// A beam split by two cracks (examples/john_shah.toml) at a cell 50 times finer: refused at once
// by the walk-free estimate (31281 MiB against a limit of 30000, which the grid with its 1.74e8
// particles alone, 23923 MiB, fits), where the walks over its three
// parts took 2 min 14 s before the same refusal.
TEST(RunLimits, a_body_split_by_its_cracks_is_refused_before_its_parts_are_walked) {
  const std::string dir = std::string(RUPTURE_SOURCE_DIR) + "/examples/";
  std::string e;
  try {
    load_case(dir + "john_shah.toml", {"parameters.h=2e-5", "solver.memory_limit_mib=30000"});
  } catch (const InputError& x) {
    e = x.what();
  }
  EXPECT_NE(e.find("'solver.memory_limit_mib' = 30000"), std::string::npos) << e;
  EXPECT_NE(e.find("the case needs about 31281 MiB (memory_estimate_mib before any seed point"), std::string::npos) << e;
}
