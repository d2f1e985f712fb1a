// rupture/solver/rank_exchange.hpp
// What the time step asks of the other ranks of a distributed run (MPI), as one interface:
// State::halo (null on one process, where every call below is a no-op, the identity, or a
// throw at once). parallel/halo.hpp's Halo is its one implementation, chosen once per run by
// the split (parallel/); the solver knows nothing else of ranks, blocks or MPI, so the folders
// keep their layers (parallel/ builds on solver/, never the reverse). The calls are a few per
// step, none inside a particle loop. Each is documented where it is implemented
// (parallel/halo.hpp, parallel/halo_nested.hpp); in short:
//   halo_sum             after a scatter: every node shared with other ranks gets the sum of all
//                        their contributions, in rank order (the same bits on every copy); with
//                        the mass first it also records which rank counts the node (counts_node);
//   halo_save/_sum_added the same for what a phase adds to arrays already summed;
//   halo_sum_lanes       the same for a scratch array of `lanes` values per node (the averaged
//                        mass's products M x, solver/consistent_mass.hpp);
//   halo_lowest_region   [loads] velocity regions: every copy of a node prescribed alike;
//   counts_node          whether this rank counts a node in node-counted sums (edge work);
//   sync_interface_nodes owners send interface node arrays to the ranks that know the nodes;
//   check_faces_in_reach every known face's stencil lies in this rank's reach;
//   migrate_if_due       particles that left this rank's block go to its owner (and the split
//                        follows the load: parallel/rebalance.cpp);
//   finish_distributed_step  the step's drift bound; a failure on any rank stops every rank;
//   sum_over_ranks       element-wise sums of a few values, added in rank order (the same bits
//                        on every rank: a crack tip's J-domain maps and integrals, which every
//                        rank's growth decision reads);
//   nested_*             the same for nested levels (solver/nested_state.cpp's step);
//   fail_in_step         a failure found in a phase: thrown at once on one process, kept until
//                        the step's end on several (every rank takes part in its exchanges).
#pragma once
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "solver/state.hpp"
#include "solver/transfer.hpp"

namespace rupture {

struct RunState;  // solver/run_state.hpp
struct NestedDrift;  // solver/nested_state.hpp

using InterfaceArray = std::vector<double> CohesiveInterface::*;

class RankExchange {
 public:
  virtual ~RankExchange() = default;
  virtual void sum(State& s, std::initializer_list<NodalArray> arrays) = 0;
  virtual void save(const State& s, std::initializer_list<NodalArray> arrays) = 0;
  virtual void sum_added(State& s, std::initializer_list<NodalArray> arrays) = 0;
  virtual void sum_lanes(const State& s, double* values, int lanes) = 0;
  virtual void lowest_region(const State& s, std::vector<int>& mark, std::vector<std::size_t>& changed) = 0;
  virtual bool counts_node(const State& s, int field, std::size_t node) const = 0;
  virtual void sync_interface_nodes(State& s, CohesiveInterface& c,
                                    std::initializer_list<InterfaceArray> arrays) = 0;
  virtual void check_faces_in_reach(State& s) = 0;
  virtual void migrate_if_due(State& s) = 0;
  virtual void finish_step(State& s, double drift_at_start) = 0;
  virtual void send_to_level_owners(RunState& n) = 0;
  virtual void migrate_levels_if_due(RunState& n) = 0;
  virtual void finish_nested_step(RunState& n, const NestedDrift& before) = 0;
  virtual double min_over_ranks(double v) const = 0;
  virtual void max_over_ranks(double* values, std::size_t n) const = 0;  // element-wise, in place
  virtual void sum_in_rank_order(double* values, std::size_t n) const = 0;
  // A distributed nested level: the split fixed its field windows to its reach.
  virtual bool fixes_windows() const = 0;

  // What the step keeps here: the step's first failure on this rank (fail_in_step), and the
  // wall time spent inside the exchanges so far, s (the cohesive timer leaves it out).
  std::string failure;
  double exchange_seconds = 0.0;
};

inline void halo_sum(State& s, std::initializer_list<NodalArray> arrays) {
  if (s.halo) s.halo->sum(s, arrays);
}
// values[lanes * e + c], e a node of the fields (GridFields::index), c < lanes.
inline void halo_sum_lanes(const State& s, double* values, int lanes) {
  if (s.halo) s.halo->sum_lanes(s, values, lanes);
}
inline void halo_save(State& s, std::initializer_list<NodalArray> arrays) {
  if (s.halo) s.halo->save(s, arrays);
}
inline void halo_sum_added(State& s, std::initializer_list<NodalArray> arrays) {
  if (s.halo) s.halo->sum_added(s, arrays);
}
inline void halo_lowest_region(State& s, std::vector<int>& mark, std::vector<std::size_t>& changed) {
  changed.clear();
  if (s.halo) s.halo->lowest_region(s, mark, changed);
}
inline bool counts_node(const State& s, int field, std::size_t node) {
  return !s.halo || s.halo->counts_node(s, field, node);
}
inline void sync_interface_nodes(State& s, CohesiveInterface& c, std::initializer_list<InterfaceArray> arrays) {
  if (s.halo) s.halo->sync_interface_nodes(s, c, arrays);
}
inline void check_faces_in_reach(State& s) {
  if (s.halo) s.halo->check_faces_in_reach(s);
}
inline void migrate_if_due(State& s) {
  if (s.halo) s.halo->migrate_if_due(s);
}
inline void finish_distributed_step(State& s, double drift_at_start) {
  if (s.halo) s.halo->finish_step(s, drift_at_start);
}
inline double min_over_ranks(const State& s, double v) { return s.halo ? s.halo->min_over_ranks(v) : v; }
inline void max_over_ranks(const State& s, double* values, std::size_t n) {
  if (s.halo) s.halo->max_over_ranks(values, n);
}
inline void sum_over_ranks(const State& s, double* values, std::size_t n) {
  if (s.halo) s.halo->sum_in_rank_order(values, n);
}
inline void fail_in_step(State& s, const std::string& what) {
  if (!s.halo) throw SimulationError(what);
  if (s.halo->failure.empty()) s.halo->failure = what;
}
inline bool failed_in_step(const State& s) { return s.halo && !s.halo->failure.empty(); }

}  // namespace rupture
