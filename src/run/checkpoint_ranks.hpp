// rupture/run/checkpoint_ranks.hpp
// Checkpoints of a distributed run (parallel/halo.hpp), read back by any number of processes
// (1 included). Writing (collective): every rank writes its particles into a part file named
// by the step (run/checkpoint.hpp), then rank 0 writes checkpoint.bin with the run's sums
// (strain and external work, interface work: the ranks' parts added), every interface node
// from its owner and State::particle_parts = N; older parts are removed once it is in place.
// A write that fails on any rank fails on all (IoError naming the file). Reading: after
// read_checkpoint, the parts' particles replace the State's: each rank reads some of the parts
// and the split sends every particle to its rank.
#pragma once
#include <string>
#include <vector>

#include "input/case.hpp"
#include "parallel/comm.hpp"
#include "run/run_context.hpp"

namespace rupture {

void write_checkpoint_ranks(const std::string& dir, const CaseSource& source, RunContext& ctx,
                            const Comm& comm);

// After read_checkpoint: when the checkpoint has particle parts, loads them into ctx.s.
void read_checkpoint_particles(const std::string& dir, RunContext& ctx);

// The same for one rank of `comm`: it reads parts rank, rank + N, ... (of each nested level)
// only and returns each particle's key per level, part x 2^32 + its place in the part (the
// order read_checkpoint_particles gives), for distribute_held (parallel/halo.hpp) or
// distribute_held_nested (parallel/halo_nested.hpp) to split them.
std::vector<std::vector<double>> read_checkpoint_share(const std::string& dir, RunContext& ctx, const Comm& comm);

}  // namespace rupture
