// rupture/run/checkpoint_ranks.hpp
// Checkpoints of a distributed run (parallel/halo.hpp), read back by any number of processes
// (1 included). Writing (collective): every rank writes its particles into a part file named
// by the step (io/checkpoint.hpp), then rank 0 writes checkpoint.bin with the run's sums
// (strain and external work, interface work: the ranks' parts added), every interface node
// from its owner and State::particle_parts = N; older parts are removed once it is in place.
// A write that fails on any rank fails on all (IoError naming the file). Reading: after
// read_checkpoint, the parts' particles replace the State's (every rank reads all parts; the
// split that follows keeps each rank's own).
#pragma once
#include <string>

#include "io/case.hpp"
#include "parallel/comm.hpp"
#include "run/run_context.hpp"

namespace rupture {

void write_checkpoint_ranks(const std::string& dir, const CaseSource& source, RunContext& ctx,
                            const Comm& comm);

// After read_checkpoint: when the checkpoint has particle parts, loads them into ctx.s.
void read_checkpoint_particles(const std::string& dir, RunContext& ctx);

}  // namespace rupture
