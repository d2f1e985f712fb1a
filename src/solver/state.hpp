// rupture/solver/state.hpp
// One level of a run: one lattice (a uniform or graded grid, or one nested level), its
// particles and fields, and what is derived once from the Case for it (material stiffnesses,
// resolved boundary nodes, its interfaces, loads, step limits). A run is one or more of them
// (solver/run_state.hpp). make_state() builds a one-grid level; step() (solver/step.hpp)
// advances one grid by one time step. SI units throughout.
#pragma once
#include <cstddef>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "bc/absorbing.hpp"
#include "bc/loads.hpp"
#include "bc/velocity_bc.hpp"
#include "cohesive/interface.hpp"
#include "grid/grid.hpp"
#include "input/case.hpp"
#include "material/elastic.hpp"
#include "particles/particles.hpp"

namespace rupture {

class RankExchange;  // solver/rank_exchange.hpp (parallel/halo.hpp implements it)

// Race-free scatter without locks: particles are kept physically sorted by vertical strips
// of `strip_cells` cell columns, and inside a strip by the first node of their stencil, row
// then column (so consecutive particles touch the same nodes, runs of them all nine: the
// transfers read and write those once, and memory is walked in order). A particle in cell column c touches
// node columns c-1..c+2. With strips of 5 columns or more, strips two apart stay node-disjoint
// even when particles drift up to one column out of their strip, so strips are processed in
// two colours (even, then odd), each colour in parallel, and the sort is redone only every
// `sort_interval` steps (on a uniform lattice only once particles may also have moved half a
// cell: build_scatter_plan) or as soon as a particle drifts further (`valid` false). The
// summation order at every node is fixed by the sort, so results do not depend on the
// number of threads. 32 columns: each strip's tiles (solver/transfer.cpp) span its columns
// plus 5, so narrow strips zero, fill and add back up to twice the nodes they need, and a
// strip walks its node rows one row pitch apart, a 4 KiB page per row and grid array for
// lattices of 512 nodes or more: wider strips touch fewer pages per node (the widths
// measured: docs/performance.md, "Choices in the code"). Not wider: a level of a few hundred
// columns needs several strips per colour to keep the threads busy. The width is
// fixed (not chosen from the thread count): it sets the summation order.
// Every member must also be written in run/checkpoint.cpp, or be listed there as scratch.
struct ScatterPlan {
  int strip_cells = 32;
  int sort_interval = 25;
  int num_strips = 0;
  long sorted_step = -1;                 // step of the last sort
  bool valid = false;                    // particles within their strips' drift tolerance
  std::vector<std::size_t> strip_begin;  // particles of strip k: [strip_begin[k], strip_begin[k+1])
  std::vector<std::uint32_t> order;      // scratch for the sort
  std::vector<std::uint32_t> bucket;     // scratch: count per (strip, stencil row, column)
  std::vector<double> scratch;           // scratch for the permutation
  // Where each strip's particles lie, for the strip tiles' node rows (solver/strip_tile.hpp),
  // so no particle loop has to find them: per strip and field, the lowest and highest first
  // stencil row of its particles at the sort (row_lo > row_hi: none), and a bound on how far
  // any particle has moved since (summed by the move like State::window_drift), m, which
  // widens them by whole rows of height row_height (the smallest cell height, m).
  // The rows are not in checkpoints (rows_known is false after a restart until the next sort:
  // the tiles then find their rows from the particles; they change no result); the drift is,
  // as it decides when to re-sort (build_scatter_plan).
  bool rows_known = false;
  std::vector<int> row_lo, row_hi;  // [strip * fields + field]
  double drift = 0.0;
  double row_height = 0.0;
};

// Every member must also be written in run/checkpoint.cpp.
struct StepLimits {
  double cfl_dt = 0.0;       // cfl * h / max c_D, s (theory E6)
  double bulk_eigen_bound = 0.0;  // lambda_bulk of solver/time_step.hpp, 1/s^2
  double cohesive_dt = 0.0;  // this step's stability limit 2/sqrt(lambda_bulk + lambda_coh), s
                             // (theory E6, solver/time_step.hpp; inf without interfaces)
  double min_cohesive_dt = INFINITY;  // smallest cohesive_dt of the run so far, s
  double dt = 0.0;           // step at t = 0, s
};

// The loads of Case::loads as the time step applies them (solver/load_step.hpp). Built from the
// case by make_state() (the particles at t = 0 fix which ids a load acts on); the rest is
// rebuilt after each particle sort or each step, so nothing here is checkpointed.
struct LoadState {
  Loads spec;
  std::vector<TractionPatch> patches;                    // per traction load
  std::vector<std::vector<std::uint32_t>> region_ids;    // per velocity region: particle ids
  std::vector<PointSpread> spreads;                      // per point force
  // Rebuilt after each sort (ScatterPlan::sorted_step): particle indices of the ids above.
  long indexed_sort = -2;
  std::vector<std::uint32_t> slot_of_id;                 // id -> index
  // kAbsent: the particle is another rank's (distributed runs, parallel/halo.hpp).
  static constexpr std::uint32_t kAbsent = 0xffffffffu;
  std::vector<std::vector<std::uint32_t>> patch_index, region_index, spread_index;
  // Per-step scratch.
  std::vector<double> accel_x, accel_y;  // per field: summed body-force acceleration, m/s^2
  std::vector<double> ext_fx, ext_fy;    // per field node: this step's external force, N
  struct RegionNode {
    std::size_t node;  // field offset + node index
    int region;
    bool work = true;  // counted in the external work (a tied node's second copy is not)
  };
  std::vector<RegionNode> region_nodes;  // nodes the region particles touch this step
  std::vector<long> node_stamp;          // per field node: step + 1 when listed
  // Distributed (parallel/halo.hpp: halo_lowest_region): per field node, the region listing
  // it (-1: none), and the halo nodes another rank's region particles made listed.
  std::vector<int> node_region;
  std::vector<std::size_t> region_changed;
  bool has_forces() const {
    return !spec.tractions.empty() || !spec.body_forces.empty() || !spec.point_forces.empty();
  }
};

// The grid nodes where an interface's two fields are tied into one body (its bonded stretches).
// State::bonded holds one per interface, in the interfaces' order; after them, a tied stretch
// whose fields differ from the rest of its line's (a line on the edge of a growing crack's
// reach, whose tie the crack's junction moves to another field: solver/crack_junction.hpp) has
// an entry of its own, naming its interface (`of`) and its line (`line`, in
// InterfaceSpec::bonded_lines).
struct BondedTie {
  int upper_field = 0, lower_field = 0;
  std::vector<std::size_t> nodes;  // grid nodes, increasing
  std::size_t of = std::size_t(-1);  // a stretch's own entry: its interface's slot
  int line = -1;                     // and its tied line
  bool operator==(const BondedTie&) const = default;
};

// Grid nodes where ties that share a field meet (a split crack's junction; solver/
// cohesive_step.cpp, tie_bonded_nodes): each sums every field its ties join, once. Derived from
// State::bonded, rebuilt when its signature changes (not stored).
struct TieJunction {
  std::size_t node = 0;
  std::vector<int> fields;  // the fields its ties join, each once
  std::vector<int> group;   // per entry of fields: the first entry of its group (ties sharing a field)
};
struct TieJunctions {
  std::uint64_t signature = 0;          // of the bonded ties it was built from
  std::vector<TieJunction> nodes;
  std::vector<std::vector<char>> shared;  // per tie, per node: 1 where it is a junction's
};

// Every member must also be written in run/checkpoint.cpp (restart is bitwise), or be listed
// there as rebuilt from the case or per-step scratch.
struct State {
  Grid grid;
  GridFields fields;
  Particles particles;
  std::vector<ElasticStiffness> stiffness;  // per material
  std::vector<VelocityBC> boundary;
  std::vector<NodeBC> bc_nodes;
  std::vector<int> bc_lines;  // per condition: the grid line its edge is on now (bc/velocity_bc)
  std::vector<AbsorbingNode> absorbing;  // dashpots of the absorbing edges (bc/absorbing.hpp)
  ScatterPlan plan;
  std::vector<CohesiveInterface> interfaces;
  std::vector<BondedTie> bonded;  // per interface: its tied grid nodes (solver/cohesive_step.hpp); then stretches of their own
  TieJunctions junctions;         // derived from bonded (not stored)
  LoadState loads;  // [loads] (bc/loads.hpp): tractions, body forces, velocity regions

  Scheme scheme = Scheme::MUSL;
  double flip = 1.0;
  MassMatrix mass_matrix = MassMatrix::lumped;  // solver.mass
  // solver.mass = "averaged": the consistent mass's band, 25 per grid element ((dy + 2) 5 +
  // dx + 2, kg), and the solve's scratch (solver/consistent_mass.hpp); rebuilt every step.
  struct ConsistentMass {
    std::vector<double> band, x, r;
    std::vector<unsigned char> fixed;  // per solved lane: a prescribed value (a [boundary] node)
  } consistent_mass;
  StepLimits limits;
  double dt = 0.0;       // this step's, set by choose_time_step (solver/time_step.hpp), s
  double dt_cap = INFINITY;     // no step goes past this much time (the driver: time to the end), s
  double forced_dt = 0.0;       // > 0: a fixed step that bypasses E6 (tests of instability only), s
  double cohesive_safety = TimeSpec{}.cohesive_safety;  // dt <= safety x the cohesive limit
                                                        // (time.cohesive_safety; make_state sets it)
  double time = 0.0;     // s
  long step = 0;
  double mass_floor = 0.0;  // nodes lighter than this are treated as empty, kg
  // Field windows (solver/field_windows.hpp): not checkpointed, re-fitted after a restore.
  long windows_checked_step = -2;  // step of the last fit_field_windows
  long window_fits = 0;            // re-fits (re-allocations) so far
  double window_drift = 0.0;       // bound on any particle's move since the last measure, m
  // Ties that follow the material (solver/tie_follow.hpp): bounds on any particle's move since
  // the ties were last measured, and since t = 0, m (checkpointed; the same on every rank).
  double tie_drift = 0.0, travel = 0.0;
  double last_move = 0.0;          // the last particle move's bound, dt max |v|, m (distributed
                                   // nested levels reduce it over the ranks)
  bool whole_grid_fields = false;  // tests: every field over the whole grid (same results)

  // A distributed run (MPI): the exchanges with the other ranks the step makes
  // (solver/rank_exchange.hpp; this rank's block and neighbours: parallel/halo.hpp, halo_of);
  // null on one process. `particles` are then this rank's, and strain_work and external_work
  // this rank's parts of the run's sums.
  std::shared_ptr<RankExchange> halo;
  // Checkpoints (run/checkpoint.hpp): 0 when the particles are in the file, N when a
  // distributed run wrote them in N part files beside it (run/checkpoint_ranks.hpp).
  int particle_parts = 0;
  // Made without particles for a distributed resume (ParticleShare::none()): the
  // checkpoint brings them, so their count is the file's, not this state's (derived, not
  // written).
  bool particles_from_checkpoint = false;

  double cohesive_seconds = 0.0;  // wall time spent in the cohesive phases so far, s
  double external_work = 0.0;  // work of the prescribed velocities and loads so far, J (per unit thickness)
  double initial_energy = 0.0; // kinetic + strain energy at t = 0, J
  // E14's strain energy (solver/energy.hpp): the elastic energy at t = 0 plus the work the
  // stresses have done since, sum V sigma : d eps, J (per unit thickness)
  double strain_work = 0.0;
  // Kelvin-Voigt damping (material/elastic.hpp): the work of the viscous stresses, dissipated,
  // sum V sigma_v : d eps, J (per unit thickness; 0 without a damped material)
  double viscous_work = 0.0;
};

// Which of the case's particles a State made from it holds. One process holds every one (no
// share); a rank of a distributed run its share (parallel/halo.hpp: make_rank_state finds it);
// a resumed distributed run none (ParticleShare::none(): its checkpoint brings them). Ids are
// always the ones one process gives. With a share, the sums over particles (mass floor, initial
// and strain energy) are this process's: the distributed caller reduces them.
struct ParticleShare {
  // A uniform or graded grid: the particle centres (x, y in m) this process makes.
  std::function<bool(double, double)> own;
  // Nested levels: level l makes the centres own_level(l, x, y) accepts, with the ids
  // first_id[l] + the particle's index among level l's (empty: as one process numbers them).
  std::function<bool(int, double, double)> own_level;
  std::vector<std::uint32_t> first_id;
  bool from_checkpoint = false;  // none(): State::particles_from_checkpoint
  static ParticleShare none();
};

// One grid (uniform or graded) as one level: its particles (one velocity field per body;
// every one, or `share`'s), stiffnesses, boundary nodes, interfaces, loads and the time step,
// from a validated case. make_run_state (solver/run_state.hpp) is the set-up of a run on any
// grid; this is its one-grid level, for what steps one grid alone (tests, benchmarks).
// Throws std::logic_error for nested levels.
State make_state(const Case& c, const ParticleShare* share = nullptr);

}  // namespace rupture
