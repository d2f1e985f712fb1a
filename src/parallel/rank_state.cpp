// rupture/parallel/rank_state.cpp
// A fresh distributed run's State, made by each rank alone (parallel/halo.hpp: make_rank_state).
// Every rank walks the case's seed points to count them per cell in its share of the rows
// (solver/case_seeding.hpp; no particle stored), the counts are bisected over the ranks as
// plan_ranks bisects a whole State's (the same split), and each rank seeds only the particles
// whose cell lies in its block, with the ids one process gives them. The sums over particles a State holds become the run's by reductions: the mass
// floor from the lightest particle of the case (exact), the initial energy as the ranks' parts
// added (round-off of the one-process sum), the strain work this rank's part (as distribute).
#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <utility>
#include <stdexcept>

#include "core/errors.hpp"
#include "parallel/decomposition.hpp"
#include "parallel/halo.hpp"
#include "parallel/halo_nested.hpp"
#include "solver/case_seeding.hpp"
#include "solver/energy.hpp"

namespace rupture {

RunState make_rank_state(const Case& c, const Comm& comm) {
  if (c.grid.nested) return make_nested_rank_state(c, comm);  // parallel/halo_nested.hpp
  const Grid g = build_grid(c.grid);
  const int cols = g.x.cells, rows = g.y.cells;
  // This rank counts the case's points in the rows of cells r, r + N, ... (a count of those
  // rows only), and the bisection sums the blocks' slices over the ranks: no rank holds a
  // count of the whole lattice, and the split is the one of the whole count.
  const int N = comm.size(), me = comm.rank();
  const int my_rows = std::max(0, (rows - me + N - 1) / N);
  std::vector<std::uint32_t> count(std::size_t(cols) * std::size_t(my_rows), 0);
  double lightest = std::numeric_limits<double>::max();
  for_each_case_point(c, g, [&](const SeedPoint& p, std::size_t body, std::uint32_t) {
    const int j = std::clamp(g.y.cell_of(p.y), 0, rows - 1);
    if (j % N != me) return;
    const int i = std::clamp(g.x.cell_of(p.x), 0, cols - 1);
    ++count[std::size_t(i) + std::size_t(j / N) * std::size_t(cols)];
    // The mass append_seed_point gives it (particles/seed.cpp).
    lightest = std::min(lightest, c.materials[std::size_t(c.bodies[body].material)].density * p.lx * p.ly);
  });
  std::vector<CellCount> mine_count;
  for (std::size_t k = 0; k < count.size(); ++k)
    if (count[k] > 0) mine_count.push_back({int(k % std::size_t(cols)), int(k / std::size_t(cols)) * N + me, count[k]});
  count = {};
  Decomposition d;
  try {
    d = bisect_over_ranks(mine_count, cols, rows, N, [&comm](double* v, int n) { comm.sum(v, n); });
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("mpirun -n {}: {}", comm.size(), e.what()));
  }
  const CellBlock mine = d.block[std::size_t(comm.rank())];
  ParticleShare share;
  share.own = [&](double x, double y) {
    const int i = std::clamp(g.x.cell_of(x), 0, cols - 1), j = std::clamp(g.y.cell_of(y), 0, rows - 1);
    return i >= mine.c0 && i < mine.c1 && j >= mine.r0 && j < mine.r1;
  };
  RunState r = make_run_state(c, &share);
  State& s = r.levels[0];
  attach_halo(s, comm);
  set_blocks(s, d.block);
  r.halo = s.halo;
  s.mass_floor = 1e-20 * comm.min(lightest);  // solver/setup.cpp: the case's lightest particle
  // E14: the strain work starts from this rank's part of the elastic energy (make_run_state
  // measured it on this rank's particles); the initial energy is the run's.
  r.initial_energy = s.initial_energy = comm.sum(kinetic_energy(s.particles) + s.strain_work);
  collect_run_sums(r);
  return r;
}

}  // namespace rupture

namespace rupture {

void distribute_held(State& s, const Comm& comm, const std::vector<double>& key) {
  Particles& P = s.particles;
  const int cols = s.grid.x.cells, rows = s.grid.y.cells;
  std::vector<int> cell(P.size());
  std::vector<std::pair<long, double>> count;
  for (std::size_t p = 0; p < P.size(); ++p) {
    cell[p] = std::clamp(s.grid.x.cell_of(P.x[p]), 0, cols - 1) + std::clamp(s.grid.y.cell_of(P.y[p]), 0, rows - 1) * cols;
    count.push_back({cell[p], 1.0});
  }
  // The split of every rank's particles, their slices summed over the ranks (no rank holds
  // the lattice's count: parallel/decomposition.hpp).
  Decomposition d;
  try {
    d = bisect_over_ranks(cell_counts(std::move(count), cols), cols, rows, comm.size(),
                          [&comm](double* v, int n) { comm.sum(v, n); });
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("mpirun -n {}: {}", comm.size(), e.what()));
  }
  const BlockLocator locate(d.block, rows);
  // Every particle (its key after it) to its block's rank, this rank's own included.
  constexpr std::size_t kRecord = Particles::kPacked + 1;
  std::vector<std::vector<unsigned char>> send(std::size_t(comm.size())), recv;
  for (std::size_t p = 0; p < P.size(); ++p) {
    std::vector<unsigned char>& out = send[std::size_t(locate.owner(cell[p] % cols, cell[p] / cols))];
    double rec[kRecord];
    P.pack(p, rec);
    rec[Particles::kPacked] = key[p];
    const std::size_t at = out.size();
    out.resize(at + sizeof rec);
    std::memcpy(out.data() + at, rec, sizeof rec);
  }
  P = Particles();
  comm.all_to_all(send, recv);
  send.clear();
  std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>> order;  // key, (from, at)
  for (std::size_t q = 0; q < recv.size(); ++q)
    for (std::size_t at = 0; at + kRecord * sizeof(double) <= recv[q].size(); at += kRecord * sizeof(double)) {
      double k;
      std::memcpy(&k, recv[q].data() + at + Particles::kPacked * sizeof(double), sizeof k);
      order.push_back({k, {q, at}});
    }
  std::sort(order.begin(), order.end());
  for (const auto& o : order) {
    double rec[Particles::kPacked];
    std::memcpy(rec, recv[o.second.first].data() + o.second.second, sizeof rec);
    P.push_packed(rec);
  }
  attach_halo(s, comm);
  set_blocks(s, d.block);
  // The run's sums stay on rank 0 (as distribute of a restored State).
  if (comm.rank() > 0) {
    s.strain_work = s.external_work = s.viscous_work = 0.0;
    for (CohesiveInterface& c : s.interfaces) c.work = 0.0;
  }
}

}  // namespace rupture
