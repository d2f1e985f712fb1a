// rupture/run/checkpoint_ranks.cpp
#include "run/checkpoint_ranks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "run/checkpoint.hpp"
#include "run/checkpoint_checks.hpp"
#include "parallel/halo.hpp"
#include "solver/run_state.hpp"

namespace rupture {
namespace {

// Every rank learns whether the phase failed anywhere; the first failure's message is thrown
// as IoError on all ranks.
void agree(const Comm& comm, const std::string& failure) {
  const int failed = comm.first_with(!failure.empty());
  if (failed < 0) return;
  throw IoError(comm.broadcast(failure, failed));
}

// The States whose particles and sums a checkpoint stores: the run's levels (one grid: one).
std::vector<State*> parts_of(RunState& s) {
  std::vector<State*> out;
  for (State& l : s.levels) out.push_back(&l);
  return out;
}

// Every rank learns whether reading failed anywhere; the first failure is thrown on all ranks,
// as the kind of error it was (InputError: a bad checkpoint, IoError: it could not be read).
void agree_read(const Comm& comm, const std::string& failure, bool input_error) {
  const int failed = comm.first_with(!failure.empty());
  if (failed < 0) return;
  const std::string m = comm.broadcast((input_error ? "I" : "O") + failure, failed);
  if (m[0] == 'I') throw InputError(m.substr(1));
  throw IoError(m.substr(1));
}

// Part `part` of the checkpoint at s.step appended to `out`, checked against `level` (the
// State it goes into: fields, materials, lattice).
void read_part(const std::string& dir, const RunState& s, const State& level, int part, int parts, Particles& out) {
  Particles one;
  read_checkpoint_parts(dir, s.step, part, 1, parts, one);
  check_particles(one, level, "part.particles", checkpoint_part_path(dir, s.step, part));
  out.append_copy(one);
}

// Particles read from the parts become p's (its stored plan and windows were rank 0's).
void take_particles(State& p, Particles&& read) {
  p.particles = std::move(read);
  p.particle_parts = 0;
  p.plan.valid = false;  // re-sort
  p.windows_checked_step = -2;
}

}  // namespace

void write_checkpoint_ranks(const std::string& dir, const CaseSource& source, RunContext& ctx,
                            const Comm& comm) {
  RunState& s = ctx.s;
  collect_interface_state(s);  // every node from its owner
  const std::vector<State*> held = parts_of(s);
  const int n = comm.size(), parts = int(held.size()) * n;
  std::vector<CohesiveInterface*> interfaces;
  for (std::size_t k = 0; k < s.num_interfaces(); ++k) interfaces.push_back(&s.interface(k));
  // Three sums per State (the run's, then each part's): strain, external and viscous work.
  constexpr std::size_t K = 3;
  std::vector<double> sums{s.strain_work, s.external_work, s.viscous_work};
  for (const State* l : held) sums.insert(sums.end(), {l->strain_work, l->external_work, l->viscous_work});
  for (const CohesiveInterface* c : interfaces) sums.push_back(c->work);
  comm.sum(sums.data(), int(sums.size()));
  std::string failure;
  try {  // part l N + r: level l's particles of rank r (one level but for nested runs)
    for (std::size_t l = 0; l < held.size(); ++l)
      write_checkpoint_part(dir, s.step, int(l) * n + comm.rank(), parts, held[l]->particles);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  agree(comm, failure);  // every part is in place before checkpoint.bin names them
  if (comm.rank() == 0) {
    // The run's sums and no particles (they are in the parts), then this rank's own back.
    const std::size_t L = held.size();
    std::vector<Particles> mine(L);
    std::vector<double> own(K * L + K);
    own[0] = s.strain_work, own[1] = s.external_work, own[2] = s.viscous_work;
    for (std::size_t l = 0; l < L; ++l) {
      std::swap(mine[l], held[l]->particles);
      own[K + K * l] = held[l]->strain_work, own[K + K * l + 1] = held[l]->external_work;
      own[K + K * l + 2] = held[l]->viscous_work;
      held[l]->particle_parts = n;
    }
    std::vector<double> work;
    for (const CohesiveInterface* c : interfaces) work.push_back(c->work);
    const auto set = [&](const std::vector<double>& v) {  // run's and each part's sums
      s.strain_work = v[0], s.external_work = v[1], s.viscous_work = v[2];
      for (std::size_t l = 0; l < L; ++l) {
        held[l]->strain_work = v[K + K * l], held[l]->external_work = v[K + K * l + 1];
        held[l]->viscous_work = v[K + K * l + 2];
      }
    };
    set(sums);
    for (std::size_t k = 0; k < interfaces.size(); ++k) interfaces[k]->work = sums[K + K * L + k];
    try {
      write_checkpoint(dir, source, ctx);
    } catch (const std::exception& e) {
      failure = e.what();
    }
    for (std::size_t l = 0; l < L; ++l) {
      held[l]->particle_parts = 0;
      std::swap(mine[l], held[l]->particles);
    }
    set(own);
    for (std::size_t k = 0; k < interfaces.size(); ++k) interfaces[k]->work = work[k];
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
  RunState& s = ctx.s;
  if (s.levels[0].particle_parts == 0) return;
  const std::vector<State*> held = parts_of(s);
  const int n = s.levels[0].particle_parts, parts = int(held.size()) * n;
  // The set-up state holds the case's particles: the parts hold the same ids.
  std::vector<std::uint32_t> expected, ids;
  for (const State* l : held) expected.insert(expected.end(), l->particles.id.begin(), l->particles.id.end());
  std::sort(expected.begin(), expected.end());
  std::vector<Particles> read(held.size());
  for (std::size_t l = 0; l < held.size(); ++l) {
    for (int r = 0; r < n; ++r) read_part(dir, s, *held[l], int(l) * n + r, parts, read[l]);
    ids.insert(ids.end(), read[l].id.begin(), read[l].id.end());
  }
  check_particle_ids(std::move(ids), expected, "part.particles.id (every part)", checkpoint_part_path(dir, s.step, 0));
  for (std::size_t l = 0; l < held.size(); ++l) take_particles(*held[l], std::move(read[l]));
  s.merged_step = -1;  // the writers' merged particles anew
}

std::vector<std::vector<double>> read_checkpoint_share(const std::string& dir, RunContext& ctx, const Comm& comm) {
  RunState& s = ctx.s;
  const std::vector<State*> held = parts_of(s);
  const int n = s.levels[0].particle_parts, parts = int(held.size()) * n;
  std::vector<std::vector<double>> keys(held.size());
  std::vector<Particles> mine(held.size());
  std::string failure;
  bool input_error = false;
  try {  // every rank reaches the agreement below, also when its parts are bad
    for (std::size_t l = 0; l < held.size(); ++l)
      for (int part = comm.rank(); part < n; part += comm.size()) {
        const std::size_t before = mine[l].size();
        read_part(dir, s, *held[l], int(l) * n + part, parts, mine[l]);
        for (std::size_t k = before; k < mine[l].size(); ++k) keys[l].push_back(double(part) * 4294967296.0 + double(k - before));
      }
  } catch (const InputError& e) {
    failure = e.what(), input_error = true;
  } catch (const std::exception& e) {
    failure = e.what();
  }
  agree_read(comm, failure, input_error);
  // No rank holds the case's particles: every id is below the run's count (the loads and
  // stations index by id).
  long count = 0;
  for (const Particles& p : mine) count += long(p.size());
  const long total = comm.sum(count);
  failure.clear();
  try {
    for (std::size_t l = 0; l < held.size(); ++l)
      check_ids_below(mine[l], std::uint64_t(total), fmt::format("part.particles.id (level {}: the parts rank {} read, in order)", l, comm.rank()),
                      fmt::format("{}/checkpoint/particles_{}_*.bin", dir, s.step));
  } catch (const InputError& e) {
    failure = e.what();
  }
  agree_read(comm, failure, true);
  for (std::size_t l = 0; l < held.size(); ++l) take_particles(*held[l], std::move(mine[l]));
  s.merged_step = -1;  // the writers' merged particles anew
  return keys;
}

}  // namespace rupture
