// rupture/fuzz/fuzz_entry.cpp
#include "fuzz_entry.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>

#include "cohesive/mach_angle.hpp"
#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "run/checkpoint.hpp"
#include "run/checkpoint_checks.hpp"
#include "run/run_context.hpp"
#include "solver/nested_state.hpp"
#include "solver/step.hpp"
#include "solver/summary.hpp"

namespace rupture::fuzz {

std::string checkpoint_case_toml() {
  return R"(title = "checkpoint fuzzing: a plate with a weak plane"
[model]
plane = "strain"
[materials.homalite]
youngs_modulus = 5.2e9
poisson_ratio = 0.34
density = 1246.0
[grid]
min = [0.0, -0.001]
max = [0.02, 0.001]
cell_size = 0.5e-3
particles_per_cell = 2
[bodies.upper]
material = "homalite"
min = [0.0, 0.0]
max = [0.02, 0.001]
[bodies.lower]
material = "homalite"
min = [0.0, -0.001]
max = [0.02, 0.0]
[interface.weak_plane]
upper_body = "upper"
lower_body = "lower"
y = 0.0
start = 0.0
end = 0.015
segments = 60
sigma_max = 24e6
tau_max = 24e6
delta_n = 0.4e-6
q = 1.0
r = 0.0
bonded_to = 0.02
[time]
end = 2e-6
cfl = 0.4
[solver]
scheme = "MUSL"
flip = 1.0
[boundary.impact]
edge = "left"
from = -0.001
to = 0.0
component = "x"
function = "constant"
velocity = 20.0
[output]
history_interval = 0.1e-6
snapshot_interval = 1e-6
interface_interval = 1e-6
)";
}

namespace {

struct Prepared {
  Case c;
  CaseSummary summary;
  std::string dir;
};

const Prepared& prepared() {
  static const Prepared p = [] {
    Prepared q;
    q.c = parse_case(checkpoint_case_toml(), {}, "fuzz case");
    q.summary = summarize(q.c);
    q.dir = (std::filesystem::temp_directory_path() / "rupture_fuzz_checkpoint").string();
    return q;
  }();
  return p;
}

}  // namespace

void reseal(std::string& bytes) {
  if (bytes.size() < 24) return;  // no body: the reader refuses it before the checksum
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a, as run/checkpoint_archive.hpp
  for (std::size_t k = 0; k + 8 < bytes.size(); ++k) h = (h ^ std::uint8_t(bytes[k])) * 1099511628211ull;
  std::memcpy(bytes.data() + bytes.size() - 8, &h, sizeof h);
}

void set_up_like_driver(RunContext& r, const Case& c, const std::string& dir) {
  r.s = make_run_state(c);
  if (c.output.snapshot_interval > 0) r.snapshots = std::make_unique<SnapshotWriter>(dir, r.s.levels[0].particles);
  for (const CohesiveInterface& ci : r.s.levels[0].interfaces) r.cracks.emplace_back(ci, 2.0 * r.s.levels[0].grid.x.h, r.s.levels[0].grid.x.h);
  r.eps = 1e-6 * r.s.dt;
  r.hist = Schedule(c.output.history_interval > 0 ? c.output.history_interval : r.s.dt);
  r.snap = Schedule(c.output.snapshot_interval);
  r.prof = Schedule(c.output.interface_interval);
  r.crack = Schedule(c.output.crack_sample_interval);
  r.mach_schedule = Schedule(c.output.mach_interval);
  r.station_schedule = Schedule(c.output.station_interval);
}

namespace {

// What a resumed run does next with the restored context, on a small scale.
void continue_run(RunContext& r, const Prepared& p) {
  RunState& s = r.s;
  for (int k = 0; k < 2 && s.time < p.c.time.end; ++k) {
    s.dt_cap = p.c.time.end - s.time;
    s.sync_by = p.c.time.end;
    step(s);
    for (std::size_t i = 0; i < r.cracks.size(); ++i) r.cracks[i].sample(s.interface(i), s.time);
    r.hist.advance(s.time, r.eps);
    r.crack.advance(s.time, r.eps);
    r.checkpoint.advance(s.time, r.eps);
  }
  (void)all_particles(s);
  (void)r.history.max_relative_error(0.0);
  (void)r.history.samples.back().relative_error();
  for (std::size_t i = 0; i < r.cracks.size(); ++i) {
    (void)r.cracks[i].samples().back();
    (void)r.cracks[i].summarize(s.interface(i), p.summary.speeds[0]);
    (void)summarize_mach(r.mach, int(i), 0.0, 1.0);
  }
  (void)checkpoint_bytes(CaseSource{}, r);
}

}  // namespace

Outcome checkpoint_one(const std::uint8_t* data, std::size_t size) {
  const Prepared& p = prepared();
  std::string bytes(reinterpret_cast<const char*>(data), size);
  reseal(bytes);
  Outcome out = Outcome::accepted;
  try {
    (void)checkpoint_source_from_bytes(bytes, "fuzz input");
  } catch (const InputError&) {
  }
  try {  // as a part file of a distributed checkpoint: its particles into the state's checks
    static const State state = make_state(p.c);
    Particles part;
    read_checkpoint_part_bytes(bytes, "fuzz input", 0, 0, 1, part);
    check_particles(part, state, "part.particles", "fuzz input");
  } catch (const InputError&) {
  }
  RunContext r;
  set_up_like_driver(r, p.c, p.dir);
  try {
    restore_run_checkpoint_bytes(bytes, "fuzz input", r);
  } catch (const InputError&) {
    return Outcome::refused;
  } catch (const IoError&) {
    return Outcome::refused;
  }
  try {
    continue_run(r, p);
  } catch (const SimulationError&) {
    out = Outcome::unstable;
  }
  return out;
}

Outcome case_toml_one(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // A memory limit of 256 MiB on every input (the largest example, tpv101_2d_nested, needs 217
  // MiB, so every example stays a valid case). The reader's checks count a shaped body's
  // particles seed point by seed point, as the run will seed them, so an input whose cell the
  // fuzzer shrank a thousandfold spent minutes there under the sanitizers before its memory
  // estimate refused it (CI's 45 s run stalled on one). Above the limit the grid alone is
  // refused at once (check_grid_limits), which bounds those walks to 3e6 cells.
  try {
    (void)parse_case(text, {"solver.memory_limit_mib=256"}, "fuzz input");
  } catch (const InputError&) {
    return Outcome::refused;
  } catch (const std::exception&) {  // documented as failures of the input too (exit code 1)
    return Outcome::refused;
  }
  return Outcome::accepted;
}

}  // namespace rupture::fuzz
