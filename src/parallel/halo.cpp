// rupture/parallel/halo.cpp
#include "parallel/halo.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

#include "core/errors.hpp"
#include "parallel/agreement.hpp"
#include "parallel/halo_nested.hpp"
#include "parallel/rank_plan.hpp"
#include "solver/energy.hpp"

namespace rupture {

NodeBox reach_box(const CellBlock& b, const Grid& g, int w) {
  return NodeBox{std::max(0, b.c0 - w), std::min(g.nodes_x() - 1, b.c1 + w),
                 std::max(0, b.r0 - w), std::min(g.nodes_y() - 1, b.r1 + w)};
}

NodeBox overlap(const NodeBox& a, const NodeBox& b) {
  return NodeBox{std::max(a.i0, b.i0), std::min(a.i1, b.i1), std::max(a.j0, b.j0), std::min(a.j1, b.j1)};
}

namespace {


long place_in(const NodeBox& b, int i, int j) {
  return long(j - b.j0) * long(b.i1 - b.i0 + 1) + long(i - b.i0);
}

// The peers (ranks whose reach overlaps this rank's) and the halo nodes with their holders in
// rank order.
void build_peers(Halo& h, const Grid& g) {
  const int me = h.comm.rank();
  const auto reach_of = [&](int q) {
    return h.reaches.empty() ? reach_box(h.blocks[std::size_t(q)], g, h.halo_nodes) : h.reaches[std::size_t(q)];
  };
  h.reach = reach_of(me);
  for (int q = 0; q < int(h.blocks.size()); ++q) {
    if (q == me || h.reach.empty()) continue;
    const NodeBox box = overlap(h.reach, reach_of(q));
    if (!box.empty()) h.peers.push_back(Halo::Peer{q, box});
  }
  // Which peers hold each node of the reach (dense over the reach: its rim only is non-empty).
  const long w = long(h.reach.i1 - h.reach.i0 + 1);
  std::vector<std::vector<int>> holders(std::size_t(h.reach.count()));
  for (std::size_t k = 0; k < h.peers.size(); ++k) {
    const NodeBox& b = h.peers[k].box;
    for (int j = b.j0; j <= b.j1; ++j)
      for (int i = b.i0; i <= b.i1; ++i)
        holders[std::size_t(long(j - h.reach.j0) * w + long(i - h.reach.i0))].push_back(int(k));
  }
  h.first.assign(1, 0);
  for (int j = h.reach.j0; j <= h.reach.j1; ++j)
    for (int i = h.reach.i0; i <= h.reach.i1; ++i) {
      const std::vector<int>& on = holders[std::size_t(long(j - h.reach.j0) * w + long(i - h.reach.i0))];
      if (on.empty()) continue;
      h.node_i.push_back(i), h.node_j.push_back(j);
      bool mine_added = false;  // peers are in rank order: this rank goes before the first above it
      for (const int k : on) {
        if (!mine_added && h.peers[std::size_t(k)].rank > me) h.terms.push_back({-1, 0}), mine_added = true;
        h.terms.push_back({k, place_in(h.peers[std::size_t(k)].box, i, j)});
      }
      if (!mine_added) h.terms.push_back({-1, 0});
      h.first.push_back(h.terms.size());
    }
  h.buffers.resize(h.peers.size());
  for (std::size_t k = 0; k < h.peers.size(); ++k) h.buffers[k].rank = h.peers[k].rank;
  // Each peer box's nodes as halo nodes (halo_sum_added packs per box from per-node values).
  std::vector<long>& index = h.halo_index;
  index.assign(std::size_t(h.reach.count()), -1);
  for (std::size_t n = 0; n < h.node_i.size(); ++n)
    index[std::size_t(long(h.node_j[n] - h.reach.j0) * w + long(h.node_i[n] - h.reach.i0))] = long(n);
  h.box_node.resize(h.peers.size());
  for (std::size_t k = 0; k < h.peers.size(); ++k) {
    const NodeBox& b = h.peers[k].box;
    for (int j = b.j0; j <= b.j1; ++j)
      for (int i = b.i0; i <= b.i1; ++i)
        h.box_node[k].push_back(index[std::size_t(long(j - h.reach.j0) * w + long(i - h.reach.i0))]);
  }
}

double read_double(const std::vector<unsigned char>& buf, std::size_t k) {
  double v;
  std::memcpy(&v, buf.data() + k * sizeof(double), sizeof v);
  return v;
}

// The send buffers of Halo::sum and sum_lanes: per peer, field-major, the box's nodes row by
// row, `per_node` values per node, value(e, v) for node e of the fields (0 where the field has
// no window: this rank added nothing there); the receive buffers sized alike.
template <class Value>
void pack_peer_boxes(Halo& h, const GridFields& G, std::size_t per_node, const Value& value) {
  const std::size_t F = std::size_t(G.num_fields);
  for (std::size_t k = 0; k < h.peers.size(); ++k) {
    const NodeBox& b = h.peers[k].box;
    const std::size_t n = std::size_t(b.count()) * F * per_node;
    PeerBuffers& buf = h.buffers[k];
    buf.send.resize(n * sizeof(double));
    buf.recv.resize(n * sizeof(double));
    double* out = reinterpret_cast<double*>(buf.send.data());
    for (std::size_t f = 0; f < F; ++f)
      for (int j = b.j0; j <= b.j1; ++j)
        for (int i = b.i0; i <= b.i1; ++i) {
          const bool held = G.holds(int(f), i, j);
          const std::size_t e = held ? G.index(int(f), i, j) : 0;
          for (std::size_t v = 0; v < per_node; ++v) *out++ = held ? value(e, v) : 0.0;
        }
  }
}

}  // namespace

void Halo::exchange(bool sized) {
  const auto t0 = std::chrono::steady_clock::now();
  if (sized)
    comm.exchange_sized(buffers);
  else
    comm.exchange(buffers);
  for (const PeerBuffers& b : buffers) bytes_sent += double(b.send.size());
  exchange_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

namespace {

// lay_reach's work on this rank (no collective call).
void lay_own_reach(State& s) {
  Halo& h = halo_of(s);
  if (!s.interfaces.empty() && h.reaches.empty()) {
    // An owned node's neighbours must be known: segments longer than two cells (an interface
    // drawn with segments coarser than the grid) widen the reach from the start.
    h.face_cells = std::max(h.face_cells, longest_segment_cells(s) - 1);
    h.halo_nodes = std::max(h.halo_nodes, 1 + 2 * h.face_cells);
  }
  h.peers.clear(), h.node_i.clear(), h.node_j.clear(), h.terms.clear(), h.box_node.clear();
  build_peers(h, s.grid);
  s.bonded = h.all_bonded;  // distribute_interfaces keeps the ties of the new reach
  distribute_interfaces(s);
  s.windows_checked_step = -2;  // re-fit the windows to this rank's particles and faces
}

// This rank's reach from h.blocks and h.halo_nodes: its peers and halo nodes, the interfaces'
// owned and known nodes, the ties of the reach; the windows re-fitted. Collective (every rank
// lays its reach at the same point): a refusal on one rank (distribute_interfaces) reaches all.
void lay_reach(State& s) {
  agree_on_failure(halo_of(s).comm, [&s] { lay_own_reach(s); });
}

}  // namespace

void set_blocks(State& s, std::vector<CellBlock> blocks) {
  Halo& h = halo_of(s);
  h.blocks = std::move(blocks);
  lay_reach(s);
  s.plan.valid = false;  // re-sort (particles changed rank)
}

int reach_for_travel(double travel) { return std::max(1, int(std::ceil(travel)) + 1); }

bool reach_too_narrow(const Halo& h, double travel) {
  // Half a cell of headroom: a face moves far less than that in one step (the CFL bound), so the
  // faces are still inside the reach when check_faces_in_reach looks, later in the same step.
  return h.reaches.empty() && travel > double(h.face_cells) - 0.5;
}

void widen_interface_reach(State& s, double travel) {
  Halo& h = halo_of(s);
  collect_interface_state(s);  // the nodes this rank comes to know: their owners' state
  h.face_cells = reach_for_travel(travel);
  h.halo_nodes = 1 + 2 * h.face_cells;
  lay_reach(s);  // the particles stay on their ranks and in their order: no re-sort
  ++h.widenings;
}

void split_over_ranks(RunState& r, const Comm& comm, const SplitFrom& from) {
  if (r.is_nested()) {  // nested levels: one split for every level (parallel/halo_nested.hpp)
    if (from.held) distribute_held_nested(r, comm, *from.held);
    else distribute_nested(r, comm, from.fresh);
  } else {
    State& s = r.levels[0];
    if (from.held) distribute_held(s, comm, from.held->at(0));
    else distribute(s, comm, from.fresh);
    r.halo = s.halo;
  }
  collect_run_sums(r);  // this rank's parts of the run's sums
}

ExchangeCost exchange_cost(const RunState& r) {
  ExchangeCost cost;
  for (const State& l : r.levels) {
    if (!l.halo) continue;
    cost.bytes_sent += halo_of(l).bytes_sent;
    cost.seconds += halo_of(l).exchange_seconds;
  }
  return cost;
}

void distribute(State& s, const Comm& comm, bool fresh) {
  attach_halo(s, comm);
  set_blocks(s, plan_ranks(s, comm.size()).levels.at(0).split.block);
  keep_own_particles(s);  // every rank made the same State: the same particles, the same split
  Particles& P = s.particles;
  // E14: the strain work starts from this rank's part of the elastic energy; the initial
  // energy stays the whole run's (the history sums the parts).
  if (fresh) {
    s.strain_work = strain_energy(P, s.stiffness);
  } else if (comm.rank() > 0) {
    s.strain_work = s.external_work = s.viscous_work = 0.0;
    for (CohesiveInterface& c : s.interfaces) c.work = 0.0;
  }
}

void attach_halo(State& s, const Comm& comm) {
  auto h = std::make_shared<Halo>();
  h->comm = comm;
  h->cell = std::min(s.grid.x.h, s.grid.y.h);
  if (!s.interfaces.empty()) h->halo_nodes = kInterfaceHaloNodes;
  h->all_bonded = s.bonded;
  s.halo = h;
}

void keep_own_particles(State& s) {
  Particles& P = s.particles;
  std::vector<unsigned char> away(P.size(), 0);
  for (std::size_t p = 0; p < P.size(); ++p) {
    const int c = std::clamp(s.grid.x.cell_of(P.x[p]), 0, s.grid.x.cells - 1);
    const int r = std::clamp(s.grid.y.cell_of(P.y[p]), 0, s.grid.y.cells - 1);
    away[p] = !halo_of(s).owns_cell(c, r);
  }
  Particles others;
  P.move_marked(away, others);
}

void Halo::sum(State& s, std::initializer_list<NodalArray> arrays) {
  Halo& h = *this;
  GridFields& G = s.fields;
  const std::size_t A = arrays.size(), F = std::size_t(G.num_fields);
  pack_peer_boxes(h, G, A, [&](std::size_t e, std::size_t a) { return (G.*arrays.begin()[a])[e]; });
  h.exchange(true);
  // Every halo node: the holders' values in rank order (this rank's own in its place). With
  // the mass (the P2G sum), also whether this rank is the lowest that gave the node mass: the
  // one that counts its node sums (counts_node).
  const bool with_mass = *arrays.begin() == &GridFields::mass;
  if (with_mass) h.counts_here.assign(F * h.node_i.size(), 0);
  for (std::size_t f = 0; f < F; ++f)
    for (std::size_t n = 0; n + 1 < h.first.size(); ++n) {
      const int i = h.node_i[n], j = h.node_j[n];
      if (!G.holds(int(f), i, j)) continue;  // this rank reads nothing there
      const std::size_t e = G.index(int(f), i, j);
      std::size_t a_index = 0;
      for (const NodalArray a : arrays) {
        double sum = 0.0;
        bool first_giver = with_mass && a_index == 0;  // no lower rank gave mass so far
        for (std::size_t t = h.first[n]; t < h.first[n + 1]; ++t) {
          const Halo::Term& term = h.terms[t];
          if (term.peer < 0) {
            if (first_giver && (G.*a)[e] != 0.0) h.counts_here[f * h.node_i.size() + n] = 1, first_giver = false;
            sum += (G.*a)[e];
            continue;
          }
          const long cnt = h.peers[std::size_t(term.peer)].box.count();
          const double v = read_double(h.buffers[std::size_t(term.peer)].recv,
                                       (f * std::size_t(cnt) + std::size_t(term.place)) * A + a_index);
          if (v != 0.0) first_giver = false;
          sum += v;
        }
        (G.*a)[e] = sum;
        ++a_index;
      }
    }
}

// halo_sum_lanes: Halo::sum's exchange for `lanes` values per node of a scratch array (each
// rank's partial products over its own particles), summed in rank order at every halo node.
void Halo::sum_lanes(const State& s, double* values, int lanes) {
  Halo& h = *this;
  const GridFields& G = s.fields;
  const std::size_t L = std::size_t(lanes), F = std::size_t(G.num_fields);
  pack_peer_boxes(h, G, L, [&](std::size_t e, std::size_t c) { return values[L * e + c]; });
  h.exchange(true);
  for (std::size_t f = 0; f < F; ++f)
    for (std::size_t n = 0; n + 1 < h.first.size(); ++n) {
      if (!G.holds(int(f), h.node_i[n], h.node_j[n])) continue;
      const std::size_t e = G.index(int(f), h.node_i[n], h.node_j[n]);
      for (std::size_t c = 0; c < L; ++c) {
        double sum = 0.0;
        for (std::size_t t = h.first[n]; t < h.first[n + 1]; ++t) {
          const Halo::Term& term = h.terms[t];
          if (term.peer < 0) {
            sum += values[L * e + c];
            continue;
          }
          const long cnt = h.peers[std::size_t(term.peer)].box.count();
          sum += read_double(h.buffers[std::size_t(term.peer)].recv,
                             (f * std::size_t(cnt) + std::size_t(term.place)) * L + c);
        }
        values[L * e + c] = sum;
      }
    }
}

void Halo::save(const State& s, std::initializer_list<NodalArray> arrays) {
  Halo& h = *this;
  const GridFields& G = s.fields;
  const std::size_t A = arrays.size(), N = h.node_i.size();
  h.saved.assign(std::size_t(G.num_fields) * N * A, 0.0);
  for (std::size_t f = 0; f < std::size_t(G.num_fields); ++f)
    for (std::size_t n = 0; n < N; ++n) {
      if (!G.holds(int(f), h.node_i[n], h.node_j[n])) continue;
      const std::size_t e = G.index(int(f), h.node_i[n], h.node_j[n]);
      std::size_t a = 0;
      for (const NodalArray arr : arrays) h.saved[(f * N + n) * A + a++] = (G.*arr)[e];
    }
}

void Halo::sum_added(State& s, std::initializer_list<NodalArray> arrays) {
  Halo& h = *this;
  GridFields& G = s.fields;
  const std::size_t A = arrays.size(), F = std::size_t(G.num_fields), N = h.node_i.size();
  auto added = [&](std::size_t f, std::size_t n, std::size_t a, const NodalArray arr) {
    if (!G.holds(int(f), h.node_i[n], h.node_j[n])) return 0.0;
    return (G.*arr)[G.index(int(f), h.node_i[n], h.node_j[n])] - h.saved[(f * N + n) * A + a];
  };
  for (std::size_t k = 0; k < h.peers.size(); ++k) {
    const std::vector<long>& nodes = h.box_node[k];
    PeerBuffers& buf = h.buffers[k];
    buf.send.resize(nodes.size() * F * A * sizeof(double));
    buf.recv.resize(buf.send.size());
    double* out = reinterpret_cast<double*>(buf.send.data());
    for (std::size_t f = 0; f < F; ++f)
      for (const long n : nodes) {
        std::size_t a = 0;
        for (const NodalArray arr : arrays) *out++ = added(f, std::size_t(n), a++, arr);
      }
  }
  h.exchange(true);
  for (std::size_t f = 0; f < F; ++f)
    for (std::size_t n = 0; n < N; ++n) {
      if (!G.holds(int(f), h.node_i[n], h.node_j[n])) continue;
      const std::size_t e = G.index(int(f), h.node_i[n], h.node_j[n]);
      std::size_t a = 0;
      for (const NodalArray arr : arrays) {
        double sum = 0.0;  // the ranks' additions in rank order, onto the saved sum
        for (std::size_t t = h.first[n]; t < h.first[n + 1]; ++t) {
          const Halo::Term& term = h.terms[t];
          if (term.peer < 0) {
            sum += added(f, n, a, arr);
            continue;
          }
          const std::size_t cnt = h.box_node[std::size_t(term.peer)].size();
          sum += read_double(h.buffers[std::size_t(term.peer)].recv, (f * cnt + std::size_t(term.place)) * A + a);
        }
        (G.*arr)[e] = h.saved[(f * N + n) * A + a] + sum;
        ++a;
      }
    }
}

void Halo::lowest_region(const State& s, std::vector<int>& mark, std::vector<std::size_t>& changed) {
  changed.clear();
  Halo& h = *this;
  const GridFields& G = s.fields;
  const std::size_t F = std::size_t(G.num_fields);
  constexpr double kNone = 1e9;  // no region (region indices are small)
  for (std::size_t k = 0; k < h.peers.size(); ++k) {
    const NodeBox& b = h.peers[k].box;
    PeerBuffers& buf = h.buffers[k];
    buf.send.resize(std::size_t(b.count()) * F * sizeof(double));
    buf.recv.resize(buf.send.size());
    double* out = reinterpret_cast<double*>(buf.send.data());
    for (std::size_t f = 0; f < F; ++f)
      for (int j = b.j0; j <= b.j1; ++j)
        for (int i = b.i0; i <= b.i1; ++i) {
          const int m = G.holds(int(f), i, j) ? mark[G.index(int(f), i, j)] : -1;
          *out++ = m >= 0 ? double(m) : kNone;
        }
  }
  h.exchange(true);
  for (std::size_t f = 0; f < F; ++f)
    for (std::size_t n = 0; n + 1 < h.first.size(); ++n) {
      if (!G.holds(int(f), h.node_i[n], h.node_j[n])) continue;
      const std::size_t e = G.index(int(f), h.node_i[n], h.node_j[n]);
      double lowest = mark[e] >= 0 ? double(mark[e]) : kNone;
      for (std::size_t t = h.first[n]; t < h.first[n + 1]; ++t) {
        const Halo::Term& term = h.terms[t];
        if (term.peer < 0) continue;
        const long cnt = h.peers[std::size_t(term.peer)].box.count();
        lowest = std::min(lowest, read_double(h.buffers[std::size_t(term.peer)].recv, f * std::size_t(cnt) + std::size_t(term.place)));
      }
      if (lowest < kNone && int(lowest) != mark[e]) {
        mark[e] = int(lowest);
        changed.push_back(e);
      }
    }
}

bool Halo::counts_node(const State& s, int field, std::size_t node) const {
  const Halo& h = *this;
  const std::size_t nx = std::size_t(s.grid.nodes_x());
  const int i = int(node % nx), j = int(node / nx);
  if (h.count_by_block) {  // the rank whose block holds the node (the last cell's far nodes too)
    const CellBlock& b = h.block();
    if (b.c0 >= b.c1 || b.r0 >= b.r1) return false;  // no cell of this level in the block
    const auto in = [](int k, int lo, int hi, int last) { return k >= lo && (k < hi || (hi == last && k == last)); };
    return in(i, b.c0, b.c1, s.grid.x.cells) && in(j, b.r0, b.r1, s.grid.y.cells);
  }
  if (!h.reach.contains(i, j)) return false;  // no particle of this rank reaches it
  const long w = long(h.reach.i1 - h.reach.i0 + 1);
  const long n = h.halo_index[std::size_t(long(j - h.reach.j0) * w + long(i - h.reach.i0))];
  if (n < 0) return true;  // in no other rank's reach: this rank's alone
  return h.counts_here.size() == std::size_t(s.fields.num_fields) * h.node_i.size() &&
         h.counts_here[std::size_t(field) * h.node_i.size() + std::size_t(n)];
}

void Halo::migrate_if_due(State& s) {
  Halo& h = *this;
  h.step_start = std::chrono::steady_clock::now();
  // One reduction for both bounds: the particles' drift since the last migration and how far the
  // interfaces' faces have moved from where they were drawn (face_travel, in cells).
  double bound[2] = {h.drift, s.interfaces.empty() ? 0.0 : face_travel(s)};
  h.comm.max(bound, 2);
  if (reach_too_narrow(h, bound[1])) widen_interface_reach(s, bound[1]);
  if (bound[0] < kMigrateCells * h.cell) {
    if (s.step % s.plan.sort_interval == 0) rebalance_if_needed(s);  // a crack's load moves too
    return;
  }
  migrate_particles(s);
  rebalance_if_needed(s);
}

void migrate_particles(State& s) {
  Halo& h = halo_of(s);
  Particles& P = s.particles;
  // Destination of each particle that left the block: the peer whose block holds its cell.
  std::vector<unsigned char> leaving(P.size(), 0);
  std::vector<int> dest(P.size(), -1);
  std::vector<std::size_t> count(h.peers.size(), 0);
  for (std::size_t p = 0; p < P.size(); ++p) {
    const int c = std::clamp(s.grid.x.cell_of(P.x[p]), 0, s.grid.x.cells - 1);
    const int r = std::clamp(s.grid.y.cell_of(P.y[p]), 0, s.grid.y.cells - 1);
    if (h.owns_cell(c, r)) continue;
    for (std::size_t k = 0; k < h.peers.size(); ++k) {
      const CellBlock& b = h.blocks[std::size_t(h.peers[k].rank)];
      if (c >= b.c0 && c < b.c1 && r >= b.r0 && r < b.r1) {
        dest[p] = int(k);
        break;
      }
    }
    if (dest[p] < 0) {
      // Cannot happen while the drift bound holds; a diagnosis rather than a lost particle.
      if (h.failure.empty())
        h.failure = fmt::format(
            "particle id {} at (x, y) = ({:.6g}, {:.6g}) m, step {}, t = {:.6g} s, left rank "
            "{}'s block by more than its halo (drift bound {:.3g} cells)",
            P.id[p], P.x[p], P.y[p], s.step, s.time, h.comm.rank(), h.drift / h.cell);
      continue;
    }
    leaving[p] = 1;
    ++count[std::size_t(dest[p])];
  }
  for (std::size_t k = 0; k < h.peers.size(); ++k) {
    h.buffers[k].send.resize(count[k] * Particles::kPacked * sizeof(double));
    count[k] = 0;
  }
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (!leaving[p]) continue;
    const std::size_t k = std::size_t(dest[p]);
    double* out = reinterpret_cast<double*>(h.buffers[k].send.data()) + count[k]++ * Particles::kPacked;
    P.pack(p, out);
  }
  Particles gone;
  P.move_marked(leaving, gone);
  h.exchange(false);
  for (const PeerBuffers& b : h.buffers) {  // in rank order: the same order on every run
    const std::size_t n = b.recv.size() / (Particles::kPacked * sizeof(double));
    for (std::size_t q = 0; q < n; ++q) {
      double in[Particles::kPacked];
      std::memcpy(in, b.recv.data() + q * sizeof in, sizeof in);
      P.push_packed(in);
    }
  }
  h.drift = 0.0;
  ++h.migrations;
  s.plan.valid = false;  // re-sort (and re-measure the windows) before the scatter
}

void Halo::finish_step(State& s, double drift_at_start) {
  Halo& h = *this;
  h.drift += s.plan.drift - drift_at_start;
  h.step_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - h.step_start).count();
  h.particle_steps += double(s.particles.size());
  h.node_steps += h.owned_nodes;
  const int failed = h.comm.first_with(!h.failure.empty());
  if (failed < 0) return;
  const std::string what = h.comm.broadcast(h.failure, failed);
  h.failure.clear();
  throw SimulationError(h.comm.size() > 1 ? fmt::format("{} (rank {})", what, failed) : what);
}

double sum_over_ranks(const State& s, double v) { return s.halo ? halo_of(s).comm.sum(v) : v; }
long sum_over_ranks(const State& s, long v) { return s.halo ? halo_of(s).comm.sum(v) : v; }
double sum_over_ranks(const RunState& r, double v) { return r.halo ? halo_of(r).comm.sum(v) : v; }
long sum_over_ranks(const RunState& r, long v) { return r.halo ? halo_of(r).comm.sum(v) : v; }

}  // namespace rupture
