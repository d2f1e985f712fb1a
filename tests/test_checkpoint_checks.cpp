// Checkpoints as untrusted input (run/checkpoint_checks.hpp): every invariant a restored run
// relies on is checked, a violation refused with an InputError naming the entry, the value and
// what is allowed; damaged files (bytes changed, checksum recomputed) restore cleanly or are
// refused, never crash; only regular files are read, bounded by their size.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include "core/errors.hpp"
#include "fuzz_entry.hpp"
#include "input/case_toml.hpp"
#include "run/checkpoint.hpp"
#include "run/checkpoint_checks.hpp"
#include "solver/energy.hpp"
#include "solver/step.hpp"

using namespace rupture;

namespace {

// Per process: ctest runs this file's tests side by side.
std::string scratch_dir(const char* name) {
  const auto d = std::filesystem::temp_directory_path() / (std::string(name) + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d.string();
}

const Case& plate() {
  static const Case c = parse_case(fuzz::checkpoint_case_toml());
  return c;
}

// The plate after `steps` steps, with the records a run keeps.
void run_plate(RunContext& r, int steps) {
  fuzz::set_up_like_driver(r, plate(), scratch_dir("rupture_test_ckpt_checks"));
  auto record = [&]() {
    r.history.samples.push_back(EnergySample{r.s.time, kinetic_energy(r.s.levels[0].particles),
                                             strain_energy(r.s.levels[0].particles, r.s.levels[0].stiffness), r.s.external_work,
                                             r.s.initial_energy});
    for (std::size_t i = 0; i < r.cracks.size(); ++i) r.cracks[i].sample(r.s.levels[0].interfaces[i], r.s.time);
  };
  record();
  for (int k = 0; k < steps; ++k) {
    step(r.s);
    record();
  }
}

const CaseSource kSource{"title = \"x\"\n", "case.toml", {}};

// The checkpoint of the plate after 30 steps (past a re-sort), changed by `edit` first.
template <class Edit>
std::string edited(Edit edit) {
  RunContext a;
  run_plate(a, 30);
  edit(a);
  return checkpoint_bytes(kSource, a);
}

// The message restoring `bytes` into the plate's set-up context raises ("no error" if none).
std::string refusal(const std::string& bytes) {
  RunContext r;
  fuzz::set_up_like_driver(r, plate(), scratch_dir("rupture_test_ckpt_checks_b"));
  try {
    restore_run_checkpoint_bytes(bytes, "ckpt.bin", r);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::uint64_t fnv1a(const char* p, std::size_t n) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t k = 0; k < n; ++k) h = (h ^ std::uint8_t(p[k])) * 1099511628211ull;
  return h;
}
// The checksum recomputed, as a forger would.
void reseal(std::string& b) {
  const std::uint64_t h = fnv1a(b.data(), b.size() - 8);
  std::memcpy(b.data() + b.size() - 8, &h, 8);
}

// One entry of a checkpoint: where its count and its payload are.
struct Entry {
  std::string name;
  char kind;
  std::size_t count_at, payload_at, payload;  // payload: its bytes (0 for lists and groups)
};
// Every entry in order (the format is self-describing: run/checkpoint.cpp).
std::vector<Entry> entries(const std::string& b) {
  std::vector<Entry> out;
  std::size_t at = 16;
  while (at + 8 < b.size()) {
    std::uint32_t len = 0;
    std::memcpy(&len, b.data() + at, 4);
    Entry e{b.substr(at + 4, len), b[at + 4 + len], at + 4 + len + 3, at + 4 + len + 11, 0};
    const std::uint8_t size = std::uint8_t(b[at + 4 + len + 2]);
    std::uint64_t count = 0;
    std::memcpy(&count, b.data() + e.count_at, 8);
    e.payload = e.kind == 's' ? size : e.kind == 'v' ? count * size : e.kind == 't' ? count : 0;
    at = e.payload_at + e.payload;
    out.push_back(e);
  }
  return out;
}
// The n-th entry named `name`.
Entry entry(const std::string& b, const std::string& name, int n = 0) {
  for (const Entry& e : entries(b))
    if (e.name == name && n-- == 0) return e;
  ADD_FAILURE() << "no entry " << name;
  return {};
}
template <class T>
void put(std::string& b, std::size_t at, T v) {
  std::memcpy(b.data() + at, &v, sizeof v);
  reseal(b);
}

void expect_refused(const std::string& bytes, const std::vector<std::string>& words) {
  const std::string m = refusal(bytes);
  for (const std::string& w : words) EXPECT_NE(m.find(w), std::string::npos) << "expected '" << w << "' in: " << m;
}

}  // namespace

TEST(CheckpointChecks, the_plate_restores_and_continues) {
  RunContext a;
  run_plate(a, 30);
  EXPECT_GE(a.s.levels[0].plan.num_strips, 2) << "the plate spans two scatter strips";
  EXPECT_EQ(refusal(checkpoint_bytes(kSource, a)), "no error");
  const std::string bytes = checkpoint_bytes(kSource, a);
  EXPECT_EQ(fuzz::checkpoint_one(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()),
            fuzz::Outcome::accepted);
}

TEST(CheckpointChecks, particle_invariants_are_refused_naming_the_entry) {
  expect_refused(edited([](RunContext& a) { a.s.levels[0].particles.vx.pop_back(); }),
                 {"run.state.particles.vx.length = 639", "must be 640"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].particles.field[3] = 2; }),
                 {"run.state.particles.field[3] = 2", "below the case's 2 velocity fields"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].particles.material[5] = 1; }),
                 {"run.state.particles.material[5] = 1", "below the case's 1 materials"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].particles.x[2] = NAN; }), {"run.state.particles.x[2] = nan", "finite"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].particles.y[4] = 1.0; }),
                 {"run.state.particles.y[4] = 1", "inside the lattice"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].particles.half_x[1] = 0.0; }), {"run.state.particles.half_x[1] = 0"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].particles.mass[1] = -1.0; }), {"run.state.particles.mass[1] = -1", "positive"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].particles.id[0] = a.s.levels[0].particles.id[1]; }),
                 {"run.state.particles.id", "the case's particle ids, each once"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].particles.id[7] = 0xffffffffu; }), {"run.state.particles.id"});
}

TEST(CheckpointChecks, plan_boundary_and_interface_invariants_are_refused_naming_the_entry) {
  expect_refused(edited([](RunContext& a) { a.s.levels[0].plan.sort_interval = 0; }),
                 {"run.state.plan.sort_interval = 0", "at least 1"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].plan.strip_begin[1] = a.s.levels[0].particles.size() + 5; }),
                 {"run.state.plan.strip_begin[1] = 645", "must lie in"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].plan.num_strips = 7; }), {"run.state.plan.num_strips = 7"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].plan.strip_cells = 3; }), {"run.state.plan.strip_cells = 3", "must be 32"});
  expect_refused(edited([](RunContext& a) {  // a particle of strip 0 moved into strip 1's columns
                   ASSERT_TRUE(a.s.levels[0].plan.valid);
                   a.s.levels[0].particles.x[0] = 0.019;
                 }),
                 {"run.state.particles.x[0]", "drift tolerance of its strip 0"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].bc_nodes[2].node = 1u << 30; }), {"run.state.bc_nodes[2].node = 1073741824"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].bc_nodes[0].component = 2; }), {"run.state.bc_nodes[0].component = 2"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].bc_nodes[0].condition = 1; }), {"run.state.bc_nodes[0].condition = 1"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].bc_nodes[0].field = -1; }), {"run.state.bc_nodes[0].field = -1"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].bc_lines[0] = 1000; }), {"run.state.bc_lines[0] = 1000"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].particle_parts = -1; }), {"run.state.particle_parts = -1"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].interfaces[0].gp_dn.push_back(0.0); }),
                 {"run.state.interfaces[0].gp_dn.length = 241", "must be 240"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].interfaces[0].x0.pop_back(); }),
                 {"run.state.interfaces[0].x0.length = 60", "must be 61"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].interfaces[0].uy_lo[3] = 5.0; }),
                 {"run.state.interfaces[0].uy_lo[3] = 5", "outside the lattice"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].interfaces[0].gp_separated[9] = 7; }),
                 {"run.state.interfaces[0].gp_separated[9] = 7", "0 or 1"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].interfaces[0].reversal_streak[2] = -4; }),
                 {"run.state.interfaces[0].reversal_streak[2] = -4"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].limits.dt = 0.0; }), {"run.state.limits.dt = 0", "positive"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].step = -3; }), {"run.state.step = -3"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].flip = 2.0; }), {"run.state.flip = 2"});
}

TEST(CheckpointChecks, records_and_schedules_are_refused_naming_the_entry) {
  expect_refused(edited([](RunContext& a) { a.history.samples.clear(); }), {"run.history.length = 0", "at least 1"});
  expect_refused(edited([](RunContext& a) { a.hist.interval = -1.0; }), {"run.schedule.history.interval = -1"});
  expect_refused(edited([](RunContext& a) { a.snap.next = INFINITY; }), {"run.schedule.snapshot.next = inf", "finite"});
  expect_refused(edited([](RunContext& a) { a.prof.interval = 1e-30; }), {"run.schedule.interface.interval = 1e-30"});
  expect_refused(edited([](RunContext& a) { a.crack.count = -1; }), {"run.schedule.crack.count = -1"});
  expect_refused(edited([](RunContext& a) { a.crack.count = 0; a.crack.interval = 1e-13; }),
                 {"run.schedule.crack.count = 0", "intervals behind"});
  expect_refused(edited([](RunContext& a) { a.segments = 0; }), {"run.segments = 0"});
  expect_refused(edited([](RunContext& a) { a.interface_files = -2; }), {"run.interface_files = -2"});
  expect_refused(edited([](RunContext& a) {
                   MachReading m;
                   m.interface = 3;
                   a.mach.push_back(m);
                 }),
                 {"run.mach[0].interface = 3"});
  expect_refused(edited([](RunContext& a) { a.s.levels[0].limits.min_cohesive_dt = -INFINITY; }),
                 {"run.state.limits.min_cohesive_dt = -inf", "finite or +inf"});
}

// Values copied as raw bytes and counts: bools 0 or 1, enums one of their values, a count no
// bigger than the bytes left can hold (checked before anything is allocated, without wrapping).
TEST(CheckpointChecks, raw_bools_enums_and_counts_are_refused_naming_the_entry) {
  const std::string good = edited([](RunContext&) {});
  std::string b = good;
  put(b, entry(b, "valid").payload_at, std::uint8_t(2));
  expect_refused(b, {"run.state.plan.valid = 2", "0 or 1"});
  b = good;
  put(b, entry(b, "scheme").payload_at, int(7));
  expect_refused(b, {"run.state.scheme = 7", "not one of the enum's values"});
  b = good;
  put(b, entry(b, "samples").count_at, std::uint64_t(1) << 40);  // a list
  expect_refused(b, {"truncated", "run.cracks[0].samples holds 1099511627776 items"});
  b = good;
  put(b, entry(b, "x").count_at, (std::uint64_t(1) << 61) + 1);  // x 8 bytes wraps to 8
  expect_refused(b, {"truncated", "run.state.particles.x holds 2305843009213693953 values"});
  b = good;
  put(b, entry(b, "overrides").count_at, std::uint64_t(1) << 62);  // a list of texts
  expect_refused(b, {"truncated", "case.overrides"});
}

TEST(CheckpointChecks, a_part_file_with_arrays_of_different_lengths_is_refused) {
  RunContext a;
  run_plate(a, 3);
  const std::string dir = scratch_dir("rupture_test_ckpt_part");
  Particles p = a.s.levels[0].particles;
  p.sxy.pop_back();
  write_checkpoint_part(dir, 3, 0, 1, p);
  Particles out;
  try {
    read_checkpoint_parts(dir, 3, 1, out);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("part.particles.sxy.length"), std::string::npos) << e.what();
  }
  // Arrays of one length, but a particle outside the lattice: the state's check refuses it.
  p = a.s.levels[0].particles;
  p.x[0] = -1.0;
  EXPECT_THROW(check_particles(p, a.s.levels[0], "part.particles", "x"), InputError);
}

TEST(CheckpointChecks, only_a_regular_file_is_read) {
  const std::string dir = scratch_dir("rupture_test_ckpt_files");
  auto message = [](const std::string& path) {
    try {
      read_checkpoint_source(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string fifo = dir + "/fifo.bin";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(message(fifo).find("not a regular file (a FIFO)"), std::string::npos) << message(fifo);
  const std::string link = dir + "/random.bin";
  std::filesystem::create_symlink("/dev/urandom", link);
  EXPECT_NE(message(link).find("not a regular file (a character device)"), std::string::npos) << message(link);
  EXPECT_NE(message(link).find(link), std::string::npos) << "the message names the path";
  EXPECT_NE(message(dir).find("not a regular file (a directory)"), std::string::npos) << message(dir);
  // A link to a real checkpoint is followed.
  RunContext a;
  run_plate(a, 1);
  write_checkpoint(dir, kSource, a);
  std::filesystem::create_symlink(checkpoint_path(dir), dir + "/linked.bin");
  EXPECT_EQ(read_checkpoint_source(dir + "/linked.bin").text, kSource.text);
}

// Bytes changed at random (bits flipped, counts and values overwritten with edge values,
// the file cut), the checksum recomputed: each restores cleanly (and continues two steps,
// SimulationError allowed) or is refused with InputError/IoError.
TEST(CheckpointChecks, mutated_checkpoints_restore_or_are_refused_never_crash) {
  RunContext a;
  run_plate(a, 30);
  const std::string good = checkpoint_bytes(kSource, a);
  const std::vector<Entry> all = entries(good);
  const std::uint64_t edge[] = {0, 1, 2, 0xff, 0x7fffffff, 0x80000000u, 0xffffffffu, std::uint64_t(-1),
                                std::uint64_t(1) << 32, std::uint64_t(1) << 62, 0x7ff0000000000000ull /* inf */,
                                0x7ff8000000000000ull /* nan */, 0xfff0000000000000ull, 0x3ff0000000000000ull /* 1.0 */};
  int counts[3] = {0, 0, 0};
  const int trials = 600;
  for (int t = 0; t < trials; ++t) {
    std::mt19937_64 rng{std::uint64_t(t)};
    std::string b = good;
    const int kind = int(rng() % 4);
    const Entry& e = all[rng() % all.size()];
    if (kind == 0) {  // bits anywhere
      for (int k = 0, n = 1 + int(rng() % 4); k < n; ++k) b[16 + rng() % (b.size() - 24)] ^= char(1 << (rng() % 8));
    } else if (kind == 1) {  // an entry's count
      const std::uint64_t v = edge[rng() % std::size(edge)];
      std::memcpy(b.data() + e.count_at, &v, 8);
    } else if (kind == 2 && e.payload > 0) {  // an edge value into an entry's payload
      const std::uint64_t v = edge[rng() % std::size(edge)];
      const std::size_t at = e.payload_at + (e.payload > 8 ? 8 * (rng() % (e.payload / 8)) : 0);
      std::memcpy(b.data() + at, &v, std::min<std::size_t>(8, e.payload));
    } else {  // cut after an entry's header
      b.resize(std::min(b.size() - 8, e.payload_at + rng() % 16) + 8);
    }
    reseal(b);
    fuzz::Outcome o = fuzz::Outcome::refused;
    EXPECT_NO_THROW(o = fuzz::checkpoint_one(reinterpret_cast<const std::uint8_t*>(b.data()), b.size()))
        << "trial " << t << ", mutation " << kind << " at entry " << e.name;
    ++counts[int(o)];
  }
  std::printf("mutated checkpoints: %d restored, %d restored then unstable, %d refused\n", counts[0], counts[2], counts[1]);
  // The trials exercised both outcomes.
  EXPECT_GT(counts[int(fuzz::Outcome::accepted)] + counts[int(fuzz::Outcome::unstable)], trials / 20)
      << "restored: " << counts[0] << " + " << counts[2] << ", refused: " << counts[1];
  EXPECT_GT(counts[int(fuzz::Outcome::refused)], trials / 4)
      << "restored: " << counts[0] << " + " << counts[2] << ", refused: " << counts[1];
}
