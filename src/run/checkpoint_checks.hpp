// rupture/run/checkpoint_checks.hpp
// A checkpoint is untrusted input (a damaged disk, a foreign or edited file whose checksum was
// recomputed). run/checkpoint.cpp decodes it checking the encoding (names, types, sizes, counts
// the remaining bytes can hold, bools 0 or 1, enums one of their values, numbers finite); these
// checks then make sure every invariant the solver, trackers and writers rely on holds in what
// was decoded (array lengths, indices into the case's tables, positions inside the lattice,
// scatter-plan strips, schedules, counters), so that no byte sequence leads to undefined
// behaviour later. A refusal is an InputError naming the checkpoint, the entry (its path in
// the file, e.g. run.state.particles.field[12]), the value and what is allowed.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "output/snapshot.hpp"
#include "run/run_context.hpp"

namespace rupture {

// What the context set up from the case holds before a checkpoint overwrites it, and the
// restored one must hold as well.
struct CheckpointBaseline {
  std::vector<std::uint32_t> ids;  // every particle's id, sorted (none: a distributed resume)
  bool has_rows = false;
  SnapshotRows rows;  // the snapshot writer's rows (from the particles at t = 0)
};
CheckpointBaseline checkpoint_baseline(const RunContext& fresh);

// Every invariant of a restored context (its particles when the file holds them; a
// distributed run's part files are checked as they are read, run/checkpoint_ranks.cpp).
void check_restored(const RunContext& ctx, const CheckpointBaseline& fresh, const std::string& origin);

// What the run's records rely on (run/outputs.cpp and run/run_io.cpp read their last
// entries): the history and every crack tracker hold at least the samples a run takes at t = 0.
void check_run_records(const RunContext& ctx, const std::string& origin);

// Every array of `p` has the same length.
void check_particle_arrays(const Particles& p, const std::string& entry, const std::string& origin);
// `p` can go into `s`: arrays of one length, field and material indices inside s's tables,
// positions inside s's lattice (the bounds the time step keeps, solver/gather.cpp), positive
// mass, volume and half-widths (at most the widest cell).
void check_particles(const Particles& p, const State& s, const std::string& entry, const std::string& origin);
// The ids of `p` (sorted, `ids`) are exactly `expected` (sorted): the case's particles.
void check_particle_ids(std::vector<std::uint32_t> ids, const std::vector<std::uint32_t>& expected,
                        const std::string& entry, const std::string& origin);
// Every id of `p` is below `count` (the particles of the run: a distributed resume, where no
// rank holds the case's particles).
void check_ids_below(const Particles& p, std::uint64_t count, const std::string& entry, const std::string& origin);

}  // namespace rupture
