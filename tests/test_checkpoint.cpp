// Checkpoints (run/checkpoint.hpp): a written and re-read RunContext is bitwise the same, the
// run continues bitwise the same from it, and damaged or foreign files are refused clearly.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "run/checkpoint.hpp"
#include "solver/energy.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

// The reference problem, cropped and coarse (1 mm, uniform): 30000 particles, 12000 segments.
Case small_rosakis() {
  return load_case(
      std::string(RUPTURE_SOURCE_DIR) + "/examples/rosakis1999.toml",
      {"grid.min=[0.0,-0.06]", "grid.max=[0.075,0.04]", "bodies.upper.max=[0.075,0.04]",
       "bodies.lower.min=[0.0,-0.06]", "bodies.lower.max=[0.075,0.0]",
       "interface.weak_plane.bonded_to=0.075", "grid.cell_size=1e-3", "grid.coarse_cell_size=0",
       "boundary.impact.velocity=60"});
}

std::string scratch_dir(const char* name) {
  const auto d = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(d);
  return d.string();
}

// A context as the driver sets it up (trackers, snapshot writer), before any step.
void set_up(RunContext& r, const Case& c, const std::string& dir) {
  r.s = make_run_state(c);
  for (std::size_t k = 0; k < r.s.levels[0].interfaces.size(); ++k) r.cracks.emplace_back(r.s.levels[0].interfaces[k], 2e-3);
  r.snapshots = std::make_unique<SnapshotWriter>(dir, r.s.levels[0].particles);
}

void advance(RunContext& r, int steps) {
  for (int k = 0; k < steps; ++k) {
    r.s.dt = r.s.limits.dt;
    step(r.s);
    r.history.samples.push_back(EnergySample{r.s.time, kinetic_energy(r.s.levels[0].particles),
                                             strain_energy(r.s.levels[0].particles, r.s.levels[0].stiffness), r.s.external_work,
                                             r.s.initial_energy});
    for (std::size_t i = 0; i < r.cracks.size(); ++i)
      r.cracks[i].sample(r.s.levels[0].interfaces[i], r.s.time);
  }
}

template <class T>
bool bitwise_equal(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

const CaseSource kSource{"title = \"x\"\n", "case.toml", {"time.end=1e-6", "grid.cell_size=1e-3"}};

}  // namespace

// A schedule with no interval never fires and advancing it returns at once (a run stopped by a
// signal advances the checkpoint schedule even when no checkpoint interval was given: it once
// spun there forever).
TEST(Schedule, fires_at_multiples_and_never_without_an_interval) {
  Schedule none;
  EXPECT_FALSE(none.due(1.0, 0.0));
  none.advance(1.0, 0.0);
  EXPECT_EQ(none.next, 0.0);
  Schedule every(0.25);
  EXPECT_FALSE(every.due(0.2, 0.0));
  EXPECT_TRUE(every.due(0.25, 0.0));
  every.advance(0.6, 0.0);
  EXPECT_DOUBLE_EQ(every.next, 0.75);
  EXPECT_EQ(every.count, 3);
}

TEST(Checkpoint, round_trip_is_bitwise_and_the_run_continues_bitwise) {
  const Case c = small_rosakis();
  const std::string dir = scratch_dir("rupture_test_checkpoint");
  RunContext a;
  set_up(a, c, dir);
  advance(a, 60);  // past a re-sort (every 25 steps): particle order differs from creation
  a.hist = Schedule(1e-7);
  a.hist.next = 3.3e-6;
  a.checkpoint = Schedule(2e-6);
  a.interface_files = 7;
  a.eps = 1e-6 * a.s.limits.dt;
  a.s.levels[0].interfaces[0].gp_separated[5] = 1;  // a separated Gauss point survives the trip
  a.s.levels[0].interfaces[0].node_crack_time[3] = 1.5e-6;
  const std::string bytes = checkpoint_bytes(kSource, a);

  RunContext b;
  set_up(b, c, dir);
  restore_checkpoint_bytes(bytes, "test", b);
  EXPECT_EQ(checkpoint_bytes(kSource, b), bytes) << "re-written checkpoint differs";
  const Particles &pa = a.s.levels[0].particles, &pb = b.s.levels[0].particles;
  EXPECT_TRUE(bitwise_equal(pa.id, pb.id)) << "particle order";
  EXPECT_TRUE(bitwise_equal(pa.x, pb.x) && bitwise_equal(pa.vy, pb.vy) &&
              bitwise_equal(pa.sxy, pb.sxy) && bitwise_equal(pa.sxx, pb.sxx) &&
              bitwise_equal(pa.volume0, pb.volume0));
  EXPECT_TRUE(bitwise_equal(a.s.levels[0].plan.strip_begin, b.s.levels[0].plan.strip_begin));
  EXPECT_EQ(a.s.levels[0].plan.sorted_step, b.s.levels[0].plan.sorted_step);
  const CohesiveInterface &ia = a.s.levels[0].interfaces[0], &ib = b.s.levels[0].interfaces[0];
  EXPECT_TRUE(bitwise_equal(ia.gp_dn, ib.gp_dn) && bitwise_equal(ia.gp_tt, ib.gp_tt) &&
              bitwise_equal(ia.gp_separated, ib.gp_separated) &&
              bitwise_equal(ia.ux_up, ib.ux_up) &&
              bitwise_equal(ia.node_crack_time, ib.node_crack_time));
  EXPECT_EQ(ia.work, ib.work);
  EXPECT_EQ(ib.spec.segments, 12000) << "the spec comes from the case, kept";
  EXPECT_EQ(a.s.time, b.s.time);
  EXPECT_EQ(a.s.step, b.s.step);
  EXPECT_EQ(a.s.external_work, b.s.external_work);
  EXPECT_EQ(b.history.samples.size(), 60u);
  EXPECT_EQ(b.cracks[0].samples().size(), 60u);
  EXPECT_EQ(b.hist.next, 3.3e-6);
  EXPECT_EQ(b.interface_files, 7);

  // Through a file: the case source comes back alone, the context as above.
  write_checkpoint(dir, kSource, a);
  const CaseSource src = read_checkpoint_source(checkpoint_path(dir));
  EXPECT_EQ(src.text, kSource.text);
  EXPECT_EQ(src.origin, kSource.origin);
  EXPECT_EQ(src.overrides, kSource.overrides);
  RunContext f;
  set_up(f, c, dir);
  read_checkpoint(checkpoint_path(dir), f);
  EXPECT_EQ(checkpoint_bytes(kSource, f), bytes);

  // Both go on 40 steps (another re-sort, the BC lines may move): still bitwise the same.
  advance(a, 40);
  advance(b, 40);
  EXPECT_TRUE(bitwise_equal(a.s.levels[0].particles.x, b.s.levels[0].particles.x));
  EXPECT_TRUE(bitwise_equal(a.s.levels[0].particles.vx, b.s.levels[0].particles.vx));
  EXPECT_TRUE(bitwise_equal(a.s.levels[0].particles.sxx, b.s.levels[0].particles.sxx));
  EXPECT_TRUE(bitwise_equal(a.s.levels[0].interfaces[0].gp_tt, b.s.levels[0].interfaces[0].gp_tt));
  a.s.levels[0].cohesive_seconds = b.s.levels[0].cohesive_seconds = 0.0;  // wall time, not a result
  EXPECT_EQ(checkpoint_bytes(kSource, a), checkpoint_bytes(kSource, b));
}

// [loads] (bc/loads.hpp) keep particle ids and re-index them after each sort: a resumed run with
// a traction, a body force and a velocity region continues bitwise, past re-sorts.
TEST(Checkpoint, a_case_with_loads_restarts_bitwise) {
  std::string text = test::strip_case_toml();
  text = text.substr(0, text.find("[boundary.push]")) + R"(
[loads.pull]
type = "traction"
from = [0.01, 0.0]
to = [0.01, 0.002]
normal = 1e6
shear = 2e5
function = "smooth_ramp"
rise_time = 1e-6
[loads.gravity]
type = "body_force"
acceleration = [0.0, -1e4]
function = "table"
table = [[0.0, 0.0], [1e-6, 1.0], [3e-6, -0.5]]
[loads.piston]
type = "velocity"
min = [0.0, 0.0]
max = [0.001, 0.002]
direction = [1.0, 1.0]
velocity = 2.0
)" + text.substr(text.find("[output]"));
  for (const std::string scheme : {"MUSL", "USL", "USF"}) {
    const Case c = parse_case(text, {"solver.scheme=\"" + scheme + "\"", "time.end=20e-6"});
    const std::string dir = scratch_dir("rupture_test_checkpoint_loads");
    RunContext a;
    set_up(a, c, dir);
    advance(a, 60);  // past two re-sorts
    const std::string bytes = checkpoint_bytes(kSource, a);
    RunContext b;
    set_up(b, c, dir);
    restore_checkpoint_bytes(bytes, "test", b);
    advance(a, 40);
    advance(b, 40);
    EXPECT_TRUE(bitwise_equal(a.s.levels[0].particles.x, b.s.levels[0].particles.x)) << scheme;
    EXPECT_TRUE(bitwise_equal(a.s.levels[0].particles.vy, b.s.levels[0].particles.vy)) << scheme;
    EXPECT_TRUE(bitwise_equal(a.s.levels[0].particles.sxy, b.s.levels[0].particles.sxy)) << scheme;
    EXPECT_EQ(a.s.external_work, b.s.external_work) << scheme;
    EXPECT_GT(a.s.external_work, 0.0) << scheme;
    EXPECT_EQ(checkpoint_bytes(kSource, a), checkpoint_bytes(kSource, b)) << scheme;
  }
}

namespace {
// The message of the InputError that restoring `bytes` into a context of case `c` raises.
std::string restore_error(const std::string& bytes, const Case& c) {
  RunContext r;
  set_up(r, c, scratch_dir("rupture_test_checkpoint_bad"));
  try {
    restore_checkpoint_bytes(bytes, "ckpt.bin", r);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(Checkpoint, truncated_corrupt_foreign_and_other_case_files_are_refused) {
  const Case c = parse_case(test::strip_case_toml());
  RunContext a;
  set_up(a, c, scratch_dir("rupture_test_checkpoint_strip"));
  advance(a, 3);
  const std::string bytes = checkpoint_bytes(kSource, a);
  ASSERT_EQ(restore_error(bytes, c), "no error");

  std::string m = restore_error(bytes.substr(0, bytes.size() / 2), c);
  EXPECT_NE(m.find("truncated or corrupt"), std::string::npos) << m;
  std::string flipped = bytes;
  flipped[bytes.size() / 3] ^= 0x10;
  m = restore_error(flipped, c);
  EXPECT_NE(m.find("checksum"), std::string::npos) << m;
  m = restore_error("title = \"a case file, not a checkpoint\"\n", c);
  EXPECT_NE(m.find("not a rupture checkpoint"), std::string::npos) << m;
  std::string other_version = bytes;
  other_version[8] = char(99);
  m = restore_error(other_version, c);
  EXPECT_NE(m.find("format version 99"), std::string::npos) << m;
  // A checkpoint of another case (another particle count) does not restore into this one.
  const Case bigger = parse_case(test::strip_case_toml(),
                                 {"grid.max=[0.02,0.002]", "bodies.strip.max=[0.02,0.002]"});
  m = restore_error(bytes, bigger);
  EXPECT_NE(m.find("does not belong to this case"), std::string::npos) << m;
  // A missing file says how checkpoints are made.
  try {
    read_checkpoint_source(scratch_dir("rupture_test_checkpoint_none") + "/checkpoint.bin");
    FAIL() << "no error for a missing checkpoint";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--checkpoint-interval"), std::string::npos) << e.what();
  }
}
