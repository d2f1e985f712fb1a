// rupture/run/checkpoint_ranks.cpp
#include "run/checkpoint_ranks.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "io/checkpoint.hpp"
#include "parallel/halo.hpp"

namespace rupture {
namespace {

// Every rank learns whether the phase failed anywhere; the first failure's message is thrown
// as IoError on all ranks.
void agree(const Comm& comm, const std::string& failure) {
  const int failed = comm.first_with(!failure.empty());
  if (failed < 0) return;
  throw IoError(comm.broadcast(failure, failed));
}

}  // namespace

void write_checkpoint_ranks(const std::string& dir, const CaseSource& source, RunContext& ctx,
                            const Comm& comm) {
  State& s = ctx.s;
  gather_interface_state(s);  // every node from its owner
  std::vector<double> sums{s.strain_work, s.external_work};
  for (const CohesiveInterface& c : s.interfaces) sums.push_back(c.work);
  comm.sum(sums.data(), int(sums.size()));
  std::string failure;
  try {
    write_checkpoint_part(dir, s.step, comm.rank(), comm.size(), s.particles);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  agree(comm, failure);  // every part is in place before checkpoint.bin names them
  if (comm.rank() == 0) {
    // The run's sums and no particles (they are in the parts), then this rank's own back.
    Particles mine;
    std::swap(mine, s.particles);
    const double strain = s.strain_work, external = s.external_work;
    std::vector<double> work;
    for (CohesiveInterface& c : s.interfaces) work.push_back(c.work);
    s.strain_work = sums[0], s.external_work = sums[1];
    for (std::size_t k = 0; k < s.interfaces.size(); ++k) s.interfaces[k].work = sums[2 + k];
    s.particle_parts = comm.size();
    try {
      write_checkpoint(dir, source, ctx);
    } catch (const std::exception& e) {
      failure = e.what();
    }
    s.particle_parts = 0;
    std::swap(mine, s.particles);
    s.strain_work = strain, s.external_work = external;
    for (std::size_t k = 0; k < s.interfaces.size(); ++k) s.interfaces[k].work = work[k];
    if (failure.empty()) {  // the parts of earlier checkpoints are no longer referred to
      const std::string keep = fmt::format("particles_{}_", s.step);
      std::error_code ec;
      for (const auto& e : std::filesystem::directory_iterator(dir + "/checkpoint", ec)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("particles_", 0) == 0 && name.rfind(keep, 0) != 0) std::filesystem::remove(e.path(), ec);
      }
    }
  }
  agree(comm, failure);
}

void read_checkpoint_particles(const std::string& dir, RunContext& ctx) {
  State& s = ctx.s;
  if (s.particle_parts == 0) return;
  Particles all;
  read_checkpoint_parts(dir, s.step, s.particle_parts, all);
  s.particles = std::move(all);
  s.particle_parts = 0;
  s.plan.valid = false;  // re-sort: the stored plan was rank 0's
  s.windows_checked_step = -2;
}

}  // namespace rupture
