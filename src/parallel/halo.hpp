// rupture/parallel/halo.hpp
// One rank's part of a distributed run (MPI) and the exchanges the time step makes with its
// neighbours. The grid's geometry (two axes) is known to every rank; its nodal arrays are not:
// each velocity field keeps its window (GridFields), fitted to the rank's own particles, so a
// rank holds the nodes of its block and a rim around it, never the whole grid.
//   - Blocks: recursive coordinate bisection by particle count (parallel/decomposition.hpp),
//     made once at t = 0; a particle belongs to the rank whose block holds its centre's cell.
//   - Reach: the nodes a rank's particles may touch, its block's nodes plus kHaloNodes on every
//     side. A particle up to 1.5 cells outside its block still touches only nodes of the reach
//     (uGIMP stencil, lp <= h/2: nodes within 1 cell + lp of the centre), and particles migrate
//     to their block's rank once any may have moved kMigrateCells since the last migration
//     (the move's drift bound, summed as for the scatter plan), so they are never further out.
//     Graded grids alike: a stencil spans cells c - 1 .. c + 2 whatever their widths, and the
//     migration counts cells of the finest size.
//   - Halo sum (after each scatter): every node in the reach of several ranks gets the sum of
//     all their contributions, added in rank order on every rank, so each copy of a node holds
//     the same bits and the grid update that follows (velocity BCs included) gives the same
//     velocities on every copy: the gathers need no second exchange. Neighbours only: the
//     ranks whose reaches overlap; nothing is reduced over all nodes.
//   - Nodal sums that count a node once (the external work of prescribed and absorbing edges)
//     count it on the lowest rank that gave it mass in the step's scatter (counts_node).
// Units: m for lengths, the nodal arrays' own units.
#pragma once
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "parallel/comm.hpp"
#include "parallel/decomposition.hpp"
#include "solver/rank_exchange.hpp"
#include "solver/run_state.hpp"
#include "solver/state.hpp"
#include "solver/transfer.hpp"

namespace rupture {

inline constexpr int kHaloNodes = 2;          // reach beyond the block's nodes, nodes
inline constexpr int kInterfaceHaloNodes = 3;  // the same with interfaces (their ghost faces)
inline constexpr double kMigrateCells = 1.0;  // particles migrate once any may have moved this far, cells

// Nodes [i0, i1] x [j0, j1], inclusive (empty when i0 > i1 or j0 > j1).
struct NodeBox {
  int i0 = 0, i1 = -1, j0 = 0, j1 = -1;
  bool empty() const { return i0 > i1 || j0 > j1; }
  long count() const { return empty() ? 0 : long(i1 - i0 + 1) * long(j1 - j0 + 1); }
  bool contains(int i, int j) const { return i >= i0 && i <= i1 && j >= j0 && j <= j1; }
};

// The nodes a block's particles may touch (its nodes and `width` more on every side, in the
// grid), and two boxes' common nodes.
NodeBox reach_box(const CellBlock& b, const Grid& g, int width);
NodeBox overlap(const NodeBox& a, const NodeBox& b);

struct Halo final : RankExchange {
  Comm comm = Comm::single();
  std::vector<CellBlock> blocks;  // every rank's block, cells (ghost cells included)
  NodeBox reach;                  // this rank's reach
  struct Peer {
    int rank = 0;
    NodeBox box;  // nodes in both reaches
  };
  std::vector<Peer> peers;  // increasing rank
  // Halo nodes (in some peer's box), each with its holders in rank order: term k of node n is
  // terms[first[n] + k]: peer index, or -1 for this rank, and the node's place in that peer's box.
  struct Term {
    int peer;
    long place;
  };
  std::vector<int> node_i, node_j;
  std::vector<std::size_t> first;  // size nodes + 1
  std::vector<Term> terms;
  std::vector<PeerBuffers> buffers;  // per peer, reused
  // Per peer: for each node of its box (row by row), the halo node it is (index into node_i).
  std::vector<std::vector<long>> box_node;
  std::vector<double> saved;  // halo_save: values at the halo nodes (field, node, array)
  std::vector<long> halo_index;  // per node of the reach (row by row): its halo node, or -1
  // Per field and halo node, this step: 1 where this rank is the lowest that gave it mass.
  std::vector<unsigned char> counts_here;
  // Nested levels (parallel/halo_nested.hpp): a node is counted by the rank whose block holds
  // it (its fields span the whole lattice, and a DOF may get its mass through the transitions).
  bool count_by_block = false;
  int halo_nodes = kHaloNodes;  // the reach's width beyond the block, nodes
  // With interfaces: how far (cells) their faces may move from where their nodes were drawn; the
  // reach is then 1 + 2 face_cells nodes (a known node's drawn cell lies within 1 + face_cells
  // cells of the block, its face that much further, its stencil one node on). Set up: 1 (3 nodes).
  int face_cells = 1;
  // Per rank, when set (nested levels: parallel/halo_nested.hpp): every rank's reach, in place
  // of its block and halo_nodes.
  std::vector<NodeBox> reaches;
  // Per interface, per peer: the owned nodes whose state it needs (it knows them), and its
  // owned nodes this rank knows (parallel/halo_interface.cpp).
  struct InterfaceLinks {
    std::vector<std::vector<std::uint32_t>> send, recv;
  };
  std::vector<InterfaceLinks> links;
  double cell = 0.0;                 // the cell size, m
  double drift = 0.0;                // bound on any particle's move since the last migration, m
  long migrations = 0;               // migrations so far
  std::vector<BondedTie> all_bonded;  // every tie (s.bonded keeps those of the reach)
  long rebalances = 0;                // new splits since the start
  long widenings = 0;                 // times the reach widened for the faces (widen_interface_reach)
  bool rebalance = true;              // false: keep the split of t = 0 (--no-rebalance)
  // The load each rank measures (parallel/rebalance.cpp): wall time of its steps, s, and the
  // particle-updates and owned interface node-updates they did; owned_nodes: now.
  double step_seconds = 0.0, particle_steps = 0.0, node_steps = 0.0, owned_nodes = 0.0;
  std::chrono::steady_clock::time_point step_start;
  std::string last_rebalance;         // what the last one did (the driver prints it)
  // What the exchanges cost so far: bytes this rank sent to its peers (and, in
  // RankExchange::exchange_seconds, the wall time inside them: the transfer and the wait for
  // the slowest peer, s). RankExchange::failure: a SimulationError caught on this rank this step.
  double bytes_sent = 0.0;
  // The neighbour exchange of `buffers` (sized: every recv already has the size that arrives),
  // timed and counted.
  void exchange(bool sized);

  const CellBlock& block() const { return blocks[std::size_t(comm.rank())]; }
  bool owns_cell(int c, int r) const {
    const CellBlock& b = block();
    return c >= b.c0 && c < b.c1 && r >= b.r0 && r < b.r1;
  }

  // The step's exchanges (solver/rank_exchange.hpp; each documented below by the name the
  // solver calls it by): this file and parallel/halo_interface.cpp, halo_nested.cpp.
  void sum(State& s, std::initializer_list<NodalArray> arrays) override;
  void save(const State& s, std::initializer_list<NodalArray> arrays) override;
  void sum_added(State& s, std::initializer_list<NodalArray> arrays) override;
  void sum_lanes(const State& s, double* values, int lanes) override;
  void lowest_region(const State& s, std::vector<int>& mark, std::vector<std::size_t>& changed) override;
  bool counts_node(const State& s, int field, std::size_t node) const override;
  void sync_interface_nodes(State& s, CohesiveInterface& c, std::initializer_list<InterfaceArray> arrays) override;
  void check_faces_in_reach(State& s) override;
  void migrate_if_due(State& s) override;
  void finish_step(State& s, double drift_at_start) override;
  void send_to_level_owners(RunState& n) override;
  void migrate_levels_if_due(RunState& n) override;
  void finish_nested_step(RunState& n, const NestedDrift& before) override;
  double min_over_ranks(double v) const override { return comm.min(v); }
  void max_over_ranks(double* values, std::size_t n) const override { comm.max(values, int(n)); }
  void sum_in_rank_order(double* values, std::size_t n) const override { comm.sum_in_rank_order(values, int(n)); }
  bool fixes_windows() const override { return !reaches.empty(); }
};

// This rank's halo of a distributed State (s.halo, which only a Halo implements).
inline Halo& halo_of(const State& s) { return static_cast<Halo&>(*s.halo); }
// The run's: its grid level's (RunState::halo).
inline Halo& halo_of(const RunState& r) { return static_cast<Halo&>(*r.halo); }

// The one split of a run over comm's ranks, by where its particles are now (bisect_over_ranks;
// every grid: nested levels are split level by level, parallel/halo_nested.hpp), each rank
// keeping its own. From what the ranks hold (SplitFrom): the same RunState on every rank (made by
// make_run_state, or restored from a one-process checkpoint; `fresh`: at t = 0), or each rank some
// of the run's particles (a resume that read some of a distributed checkpoint's parts, with
// their keys: the order one process reading every part would hold them in). The variants
// below (distribute, distribute_held and their nested forms) are its parts; outside parallel/
// call this.
struct SplitFrom {
  bool fresh = true;                                      // the same State: at t = 0, or restored
  const std::vector<std::vector<double>>* held = nullptr;  // per level, the held particles' keys
};
void split_over_ranks(RunState& r, const Comm& comm, const SplitFrom& from = {});

// split_over_ranks of the same State on every rank: splits s (uniform or graded grid, one
// lattice) among comm's ranks by its particles now, and keeps this rank's particles. The run's sums become this rank's parts: fresh (t = 0), the strain work starts
// from the rank's elastic energy; restored, rank 0 keeps the run's sums (strain and external
// work, interface work) and the others start from 0. Throws InputError for what distributed
// runs do not support yet (the message names the key).
void distribute(State& s, const Comm& comm, bool fresh = true);

// A fresh run's State on this rank of `comm`: the split of the case's particles at t = 0 (the
// one distribute makes) computed by every rank from a count of the case's seed points, and
// only this rank's particles made (parallel/rank_state.cpp; nested levels:
// parallel/halo_nested.hpp): no rank ever holds the case's particles. On one rank too (a halo
// with no peers, as distribute gives).
RunState make_rank_state(const Case& c, const Comm& comm);

// Splits s among comm's ranks when each holds some of the run's particles (a resumed run: each
// rank read some of the checkpoint's parts), as distribute splits a restored State: the
// particles bisected with their blocks' slices summed over the ranks (bisect_over_ranks: the
// split of their counts added, no rank holding the lattice's), each particle sent to its block's rank, the received ones put in increasing `key`
// (per particle: the order one process reading every part would hold them in), the run's sums
// kept on rank 0. No rank holds more than the particles it read and its own.
void distribute_held(State& s, const Comm& comm, const std::vector<double>& key);


// Gives s a halo on `comm` (no blocks yet: set_blocks follows).
void attach_halo(State& s, const Comm& comm);

// Drops the particles whose centre's cell is not in this rank's block (after a split made
// from every particle).
void keep_own_particles(State& s);

// (Re)builds this rank's halo for a new split: peers, halo nodes, interface nodes, ties; the
// particles must follow (distribute, rebalance).
void set_blocks(State& s, std::vector<CellBlock> blocks);

// Load drift (parallel/rebalance.cpp): at a migration and every ScatterPlan::sort_interval
// steps, when the largest load over the ranks (particles, plus owned interface nodes weighted
// by their measured cost) exceeds the mean by more than kRebalanceImbalance, the ranks bisect
// the load as it is now and move each particle to its new block's rank (collective).
inline constexpr double kRebalanceImbalance = 0.05;
void rebalance_if_needed(State& s);

// Lets the split follow the load (`on`) or keeps it (--no-rebalance), where the run's split can
// move at all: nested levels share one split and always keep it (parallel/halo_nested.hpp).
void enable_rebalance(RunState& r, bool on);

// A run whose split cannot follow the load (nested levels) says so when its particles drifted
// from the split by more than a rebalance would tolerate: the line to print, from the
// particles per rank at the start and at the end of the run; empty otherwise.
std::string kept_split_drift(const RunState& r, const Comm& comm, const std::vector<long>& start,
                             const std::vector<long>& end);

// What the exchanges cost so far, summed over every halo the run steps with (one per nested
// level): bytes this rank sent and the wall time in them, s.
struct ExchangeCost {
  double bytes_sent = 0.0, seconds = 0.0;
};
ExchangeCost exchange_cost(const RunState& r);

// The step's exchanges, called by the solver through solver/rank_exchange.hpp (the names it
// calls them by, then Halo's):
//
// halo_sum (Halo::sum): sums the given nodal arrays over the ranks that reach each shared node (collective among
// neighbours; nothing when s is not distributed): at every halo node each copy gets the
// holders' values added in increasing rank order from 0.0 (a rank whose field window does not
// hold the node adds 0), so every copy holds the same bits; nodes of no other rank's reach are
// left as they are.
// Side effect: when the FIRST array is &GridFields::mass (the P2G sum), it also records, per
// field and halo node, whether this rank is the lowest rank that gave the node a non-zero mass
// (Halo::counts_here, read by counts_node), from the values before the sum; a node no rank gave
// mass is counted by none. It resets those counts on every such call, and leaves them alone in
// a call whose first array is any other (forces, re-mapped momentum): pass the mass first in
// the scatter's sum, and sum it again before any node-counted sum of a new step.
//
// halo_save, halo_sum_added (Halo::save, sum_added): the same for what a phase adds to arrays that were summed already (the owners' cohesive
// forces): halo_save keeps their values at the halo nodes, halo_sum_added sums what each rank
// added since, in rank order, onto the kept values.

// Interfaces (parallel/halo_interface.cpp). A node is owned by the rank whose block holds the
// cell of its reference point; a rank knows the nodes whose reference cell lies within
// 1 + face_cells cells of its block (2 as set up: the faces touching its owned grid nodes and
// the neighbours of its owned nodes, for faces that moved less than a cell; more once the reach
// has widened, below), so their faces' stencils lie in its reach (kInterfaceHaloNodes as set
// up). Nested levels: throws InputError on every rank (agreed, a collective call) when an
// owned node's neighbour is not known (segments longer than two cells); one grid lays the reach
// wide enough for them instead (longest_segment_cells).
void distribute_interfaces(State& s);
// Faces that move far (a block sliding along a crack, a body carried across the grid): how far,
// in cells, the owned nodes' faces are from where their nodes were drawn (the largest |u_x| or
// |u_y| over this rank's owned nodes). At the start of every step (migrate_if_due, in the
// drift's reduction) the largest over the ranks decides: once it comes within half a cell of
// face_cells (reach_too_narrow), every rank sets face_cells = reach_for_travel(travel) (the
// travel rounded up, and a cell more), knows the nodes drawn within 1 + face_cells cells of
// its block and widens its reach to 1 + 2 face_cells nodes (widen_interface_reach: the
// interface state gathered, the halo and the interfaces distributed again, the windows
// re-fitted; the particles keep their ranks and their order). Nodes keep their owners (the
// block of the drawn point's cell). A node more ranks hold sums the same contributions (the
// added ones are 0), so the run is the same bit for bit. One grid; nested levels keep their
// reaches (a face may move up to a cell there).
double face_travel(const State& s);
// The most cells (along x or y) between the drawn cells of two neighbouring interface nodes:
// an owned node's neighbours must be known, so segments longer than two cells set face_cells
// to at least this less one when the reach is laid (one grid).
int longest_segment_cells(const State& s);
int reach_for_travel(double travel);
bool reach_too_narrow(const Halo& h, double travel);
void widen_interface_reach(State& s, double travel);
// How many (node, rank) pairs `rank` sends in each sync of the interfaces' nodes, with the
// split `blocks` (the exchange volume rupture check --ranks predicts).
long interface_nodes_sent(const State& s, const std::vector<CellBlock>& blocks, int rank);
// sync_interface_nodes (Halo::): owners send the listed per-node arrays to the ranks that know
// the nodes. check_faces_in_reach (Halo::): every known face's stencil lies in the reach (else
// a diagnosis for the end of the step).
// Every rank gets every node's and Gauss point's state from its owner (outputs: the interface
// profiles, crack summaries, stored energy); collect_crack_times: the nodes' crack and rupture
// times, peak slip rates and faces only (the crack tip samples and crack files);
// collect_crack_fronts: the Gauss points' jumps and separated flags only (what growth's reads
// take of the interface state: solver/crack_growth.hpp, crack_front).
// On a run: on every level holding interfaces.
void collect_interface_state(State& s);
void collect_crack_times(State& s);
void collect_interface_state(RunState& r);
void collect_crack_times(RunState& r);
void collect_crack_fronts(RunState& r);
// Crack growth on a distributed run (solver/crack_growth.hpp, which every rank runs alike:
// collect_crack_fronts for the reads, collect_interface_state once something is to grow). Growth re-lays ties over the whole grid
// (bonded_nodes): a grown segment the tie beyond its tip, a split its parent's and its
// branches', on the crack's level and, nested, on every other level. What a level's ties and
// interfaces were before growth (interface_shapes), and after it: every tie growth re-laid (its
// interface's nodes or tie lines changed, its node list changed, or it is new: a branch's)
// becomes the halo's record of that tie, and the ownership, known nodes, links and this rank's
// ties are found again (distribute_interfaces).
struct InterfaceShapes {
  std::vector<std::size_t> nodes;                  // per interface slot
  std::vector<std::vector<Polyline>> tie_lines;    // per interface slot
  std::vector<std::vector<std::size_t>> tie_nodes;  // per tie (State::bonded)
  std::vector<std::array<int, 2>> tie_fields;       // per tie: its two fields
};
InterfaceShapes interface_shapes(const State& s);
void follow_grown_interfaces(State& s, const InterfaceShapes& before);
// The run's work on interface k (the ranks' parts summed), J/m.
double interface_work(const RunState& r, std::size_t k);

// halo_lowest_region (Halo::lowest_region): [loads] velocity regions (solver/load_step.cpp): every copy of a halo node must be prescribed
// alike. `mark`, per element of s.fields: the lowest region whose particles on this rank touch
// the node, or -1; after the call, at every halo node, the lowest over the ranks holding it.
// `changed`: the elements whose mark changed (collective among neighbours).
//
// counts_node (Halo::): whether a node-counted sum (external work of prescribed and absorbing edges) counts grid
// node `node` of `field` on this rank: every copy holds the same values, and the lowest rank
// that gave the node mass in this step's scatter counts it (a fixed owner may hold no particle
// of that field near it).
//
// migrate_if_due (Halo::): at the start of a step: once a particle anywhere may have moved kMigrateCells since the last
// migration, every rank sends the particles that left its block to the block's rank, and
// marks its particles for a re-sort (collective), then rebalances when due (rebalance_if_needed).
// migrate_particles: the move itself (collective among neighbours): particles that left the block go to their
// block's rank; the drift bound restarts.
void migrate_particles(State& s);

// finish_distributed_step (Halo::finish_step): at the end of a step: adds the step's particle drift to the migration bound, and stops every
// rank together when one failed (its diagnosis, thrown as SimulationError on all ranks).
//
// fail_in_step, failed_in_step (solver/rank_exchange.hpp): a failure a phase of the step found on this rank (what, where, when): one process throws it
// at once as SimulationError; distributed, the step's first is kept, and the rank goes on
// taking part in the step's exchanges, skipping the work the failure makes unsafe
// (failed_in_step: the cohesive forces and face moves), until finish_distributed_step (or
// Halo::finish_nested_step) stops every rank together with it.

// Sum over ranks of a per-rank quantity (identity when not distributed).
double sum_over_ranks(const State& s, double v);
long sum_over_ranks(const State& s, long v);
double sum_over_ranks(const RunState& r, double v);
long sum_over_ranks(const RunState& r, long v);

}  // namespace rupture
