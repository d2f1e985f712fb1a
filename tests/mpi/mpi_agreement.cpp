// rupture/tests/mpi/mpi_agreement.cpp
// A distributed run gives the one-process answer to round-off (parallel/halo.hpp).
// Run under `mpirun -n N`: every rank steps its block of CASE for STEPS steps; rank 0 gathers
// the particles, steps the same case alone (no halo: the serial code path) and compares
// particle by particle (by id):
//   position difference / cell size, velocity difference / largest speed, stress difference /
//   largest stress component: each at most BOUND;
//   every particle exactly once (migration loses or duplicates none) and the total mass equal
//   (bit for bit: each particle's mass summed in the one-process order);
//   with --min-migrations M, at least M migrations took place (the test exercised them), with
//   --min-rebalances R at least R new splits on N > 1 ranks (the load drifted);
//   interfaces: face displacement difference / largest jump at most BOUND, the same nodes
//   cracked, their crack times equal to BOUND x the time run; with --split-interface yes, the
//   interface nodes are owned by two ranks or more (N > 1).
// Prints the measured differences as key=value lines; exit 0 when all hold.
// Usage: mpi_agreement CASE STEPS BOUND [--min-migrations M] [--min-rebalances R]
//                      [--split-interface yes]
//                      [--set key=value ...]
#include <mpi.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "input/case_toml.hpp"
#include "parallel/comm.hpp"
#include "parallel/halo.hpp"
#include "parallel/halo_nested.hpp"
#include "solver/nested_state.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"

using namespace rupture;

namespace {

void advance(RunState& s, long steps) {
  s.dt_cap = INFINITY;
  for (long k = 0; k < steps; ++k) step(s);
}

// Every rank's particles, packed, on rank 0 (empty elsewhere). A test helper: a run never
// holds all particles on one rank.
std::vector<double> gather_packed(const Particles& P, int ranks) {
  std::vector<double> mine(P.size() * Particles::kPacked);
  for (std::size_t p = 0; p < P.size(); ++p) P.pack(p, mine.data() + p * Particles::kPacked);
  int n = int(mine.size());
  std::vector<int> counts(std::size_t(ranks), 0);
  std::vector<int> offsets(std::size_t(ranks), 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  for (std::size_t r = 1; r < counts.size(); ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(std::size_t(offsets.back() + counts.back()));
  MPI_Gatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0,
              MPI_COMM_WORLD);
  return all;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const Comm world = Comm::world();
  if (argc < 4) {
    if (world.rank() == 0) fmt::print(stderr, "usage: mpi_agreement CASE STEPS BOUND [--min-migrations M] [--set k=v ...]\n");
    MPI_Finalize();
    return 2;
  }
  const std::string path = argv[1];
  const long steps = std::atol(argv[2]);
  const double bound = std::atof(argv[3]);
  long min_migrations = 0, min_rebalances = 0;
  bool split_interface = false;
  std::vector<std::string> sets;
  for (int a = 4; a + 1 < argc; a += 2) {
    const std::string key = argv[a];
    if (key == "--set") sets.push_back(argv[a + 1]);
    if (key == "--min-migrations") min_migrations = std::atol(argv[a + 1]);
    if (key == "--min-rebalances") min_rebalances = std::atol(argv[a + 1]);
    if (key == "--split-interface") split_interface = std::string(argv[a + 1]) == "yes";
  }
  const Case c = load_case(path, sets);

  // The distributed run's set-up: each rank makes its own particles only (make_rank_state).
  RunState d = make_rank_state(c, world);
  // It gives, bit for bit and in the same order, the particles, the split and the mass floor of
  // the whole set-up split afterwards (make_state + distribute); the initial energy to round-off.
  // So does a resumed run's split of particles each rank read some of (distribute_held,
  // distribute_held_nested).
  double setup_same = 1.0, initial_energy_difference = 0.0;
  {
    RunState w = make_run_state(c);
    split_over_ranks(w, world);
    const Particles &A = all_particles(w), &B = all_particles(d);
    bool same = A.x == B.x && A.y == B.y && A.vx == B.vx && A.vy == B.vy && A.mass == B.mass &&
                A.volume0 == B.volume0 && A.half_x == B.half_x && A.half_y == B.half_y && A.sxx == B.sxx &&
                A.syy == B.syy && A.sxy == B.sxy && A.field == B.field && A.material == B.material && A.id == B.id;
    same = same && w.levels[0].mass_floor == d.levels[0].mass_floor && w.strain_work == d.strain_work && !w.halo == !d.halo &&
           (!w.halo || halo_of(w).blocks.size() == halo_of(d).blocks.size());
    for (std::size_t r = 0; same && w.halo && r < halo_of(w).blocks.size(); ++r) {
      const CellBlock &a = halo_of(w).blocks[r], &b = halo_of(d).blocks[r];
      same = a.c0 == b.c0 && a.c1 == b.c1 && a.r0 == b.r0 && a.r1 == b.r1;
    }
    // A resumed run's split (distribute_held): the particles dealt to the ranks in turn, keyed
    // by their one-process index, end on the ranks and in the order distribute gives.
    {
      RunState h = make_run_state(c);
      // Deals p-th particle (of each level) to rank p mod N, keyed by p.
      const auto deal = [&](Particles& P, std::vector<double>& key) {
        std::vector<unsigned char> away(P.size(), 0);
        for (std::size_t p = 0; p < away.size(); ++p) {
          away[p] = int(p % std::size_t(world.size())) != world.rank();
          if (!away[p]) key.push_back(double(p));
        }
        Particles others;
        P.move_marked(away, others);
      };
      std::vector<std::vector<double>> keys(h.levels.size());
      for (std::size_t l = 0; l < keys.size(); ++l) deal(h.levels[l].particles, keys[l]);
      split_over_ranks(h, world, {false, &keys});
      const Particles& H = all_particles(h);
      same = same && A.x == H.x && A.y == H.y && A.vx == H.vx && A.sxy == H.sxy && A.id == H.id &&
             A.mass == H.mass && A.half_x == H.half_x && A.field == H.field;
      for (std::size_t r = 0; same && r < halo_of(w).blocks.size(); ++r) {
        const CellBlock &a = halo_of(w).blocks[r], &b = halo_of(h).blocks[r];
        same = a.c0 == b.c0 && a.c1 == b.c1 && a.r0 == b.r0 && a.r1 == b.r1;
      }
    }
    setup_same = world.min(double(same));  // every rank's
    initial_energy_difference = w.initial_energy != 0.0 ? std::fabs(d.initial_energy / w.initial_energy - 1.0)
                                                        : std::fabs(d.initial_energy);
  }
  advance(d, steps);
  const long migrations = halo_of(d).migrations, rebalances = halo_of(d).rebalances;
  collect_interface_state(d);  // every interface node from its owner (collective)
  // Interface nodes per rank: the test must split an interface between ranks.
  std::vector<double> owned(std::size_t(world.size()), 0.0);
  for (std::size_t k = 0; k < d.num_interfaces(); ++k)
    for (std::size_t q = 0; q < d.interface(k).num_nodes(); ++q) owned[std::size_t(world.rank())] += d.interface(k).owns(q);
  world.sum(owned.data(), int(owned.size()));
  int ranks_on_interfaces = 0;
  for (const double o : owned) ranks_on_interfaces += o > 0;
  const std::vector<double> all = gather_packed(all_particles(d), world.size());
  int ok = 1;
  if (world.rank() == 0) {
    RunState s = make_run_state(c);  // one process: no halo
    advance(s, steps);
    const Particles& P = all_particles(s);
    std::map<std::uint32_t, std::size_t> slot;  // id -> serial index
    double vmax = 0.0, smax = 0.0, mass = 0.0, mass_d = 0.0;
    for (std::size_t p = 0; p < P.size(); ++p) {
      slot[P.id[p]] = p;
      vmax = std::max(vmax, std::hypot(P.vx[p], P.vy[p]));
      smax = std::max({smax, std::fabs(P.sxx[p]), std::fabs(P.syy[p]), std::fabs(P.sxy[p])});
      mass += P.mass[p];
    }
    const std::size_t n = all.size() / Particles::kPacked;
    std::vector<int> seen(P.size(), 0);
    std::vector<double> mass_of(P.size(), 0.0);  // each distributed particle's mass, by serial index
    double dx = 0.0, dv = 0.0, ds = 0.0;
    for (std::size_t q = 0; q < n; ++q) {
      const double* r = all.data() + q * Particles::kPacked;  // x y vx vy mass V0 hx hy sxx syy sxy f m id
      const auto it = slot.find(std::uint32_t(r[13]));
      if (it == slot.end()) {
        ok = 0;
        continue;
      }
      const std::size_t p = it->second;
      ++seen[p];
      mass_of[p] = r[4];  // summed in the serial order below: equal sums iff equal masses
      dx = std::max({dx, std::fabs(r[0] - P.x[p]), std::fabs(r[1] - P.y[p])});
      dv = std::max({dv, std::fabs(r[2] - P.vx[p]), std::fabs(r[3] - P.vy[p])});
      ds = std::max({ds, std::fabs(r[8] - P.sxx[p]), std::fabs(r[9] - P.syy[p]), std::fabs(r[10] - P.sxy[p])});
    }
    // Interfaces: face displacements (relative to the largest jump) and node crack times.
    double du = 0.0, umax = 0.0, dcrack = 0.0;
    long cracked = 0, cracked_d = 0;
    for (std::size_t k = 0; k < s.num_interfaces(); ++k) {
      const CohesiveInterface &a = s.interface(k), &b = d.interface(k);
      for (std::size_t q = 0; q < a.num_nodes(); ++q) {
        umax = std::max({umax, std::fabs(a.jump_x(q)), std::fabs(a.jump_y(q))});
        du = std::max({du, std::fabs(a.ux_up[q] - b.ux_up[q]), std::fabs(a.uy_up[q] - b.uy_up[q]),
                       std::fabs(a.ux_lo[q] - b.ux_lo[q]), std::fabs(a.uy_lo[q] - b.uy_lo[q])});
        cracked += a.node_crack_time[q] >= 0.0, cracked_d += b.node_crack_time[q] >= 0.0;
        if (a.node_crack_time[q] >= 0.0 && b.node_crack_time[q] >= 0.0)
          dcrack = std::max(dcrack, std::fabs(a.node_crack_time[q] - b.node_crack_time[q]));
      }
    }
    const double rel_u = umax > 0 ? du / umax : du;
    if (s.num_interfaces() > 0)
      fmt::print("interface_nodes_per_rank={}\n", fmt::join(owned, ","));
    if (s.num_interfaces() > 0)
      fmt::print("interface_nodes_cracked={}\ninterface_nodes_cracked_distributed={}\n"
                 "face_displacement_difference_relative={:.3e}\ncrack_time_difference={:.3e}\n",
                 cracked, cracked_d, rel_u, dcrack);
    for (const double m : mass_of) mass_d += m;
    const long missing = std::count(seen.begin(), seen.end(), 0);
    const long repeated = long(std::count_if(seen.begin(), seen.end(), [](int k) { return k > 1; }));
    const double h = std::min(s.run_grid().x.h, s.run_grid().y.h);
    const double rel_x = dx / h, rel_v = vmax > 0 ? dv / vmax : dv, rel_s = smax > 0 ? ds / smax : ds;
    fmt::print("ranks={}\nsteps={}\nparticles={}\nparticles_distributed={}\nmissing={}\nrepeated={}\n",
               world.size(), steps, P.size(), n, missing, repeated);
    fmt::print("rebalances={}\n", rebalances);
    fmt::print("setup_identical={}\ninitial_energy_difference_relative={:.3e}\n", setup_same == 1.0 ? 1 : 0,
               initial_energy_difference);
    fmt::print("migrations={}\nmass_relative_difference={:.3e}\n", migrations, std::fabs(mass_d - mass) / mass);
    fmt::print("position_difference_over_h={:.3e}\nvelocity_difference_relative={:.3e}\n"
               "stress_difference_relative={:.3e}\nbound={:.1e}\n",
               rel_x, rel_v, rel_s, bound);
    // Mass: the same doubles summed in another order (round-off of the sum only).
    ok = ok && setup_same == 1.0 && initial_energy_difference <= bound && n == P.size() && missing == 0 && repeated == 0 &&
         mass_d == mass && rel_x <= bound && rel_v <= bound &&
         rel_s <= bound && migrations >= min_migrations &&
         (world.size() == 1 || rebalances >= min_rebalances) && cracked == cracked_d && rel_u <= bound &&
         dcrack <= bound * s.time && (!split_interface || world.size() == 1 || ranks_on_interfaces > 1);
    fmt::print("agreement={}\n", ok ? "pass" : "FAIL");
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Finalize();
  return ok ? 0 : 1;
}
