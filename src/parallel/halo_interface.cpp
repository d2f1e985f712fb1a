// rupture/parallel/halo_interface.cpp
// Cohesive interfaces and faults on a distributed run (parallel/halo.hpp). Every rank keeps the
// interface's arrays whole (a line: O(sqrt) of the grid's size), but updates only its owned
// nodes and the segments touching them; owners send ghosts' faces and stiffness to the ranks
// that know them each step, and every node's state on output.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "core/errors.hpp"
#include "core/fault_injection.hpp"
#include "parallel/halo.hpp"

namespace rupture {
namespace {

int cell_x(const Grid& g, double x) { return std::clamp(g.x.cell_of(x), 0, g.x.cells - 1); }
int cell_y(const Grid& g, double y) { return std::clamp(g.y.cell_of(y), 0, g.y.cells - 1); }

bool near_block(const CellBlock& b, int c, int r, int cells) {
  return c >= b.c0 - cells && c < b.c1 + cells && r >= b.r0 - cells && r < b.r1 + cells;
}

// A rank knows the nodes whose reference cell lies within 1 + Halo::face_cells cells of its
// block: the neighbours of its owned nodes, and the nodes whose faces may touch its own grid
// nodes (a face moves less than face_cells cells). Set up, face_cells = 1: 2 cells.
constexpr int kKnownCells = 2;

// Owner-masked arrays made whole on every rank in one reduction: each node's values from its
// owner (the sum of the owner's value and zeros, exact), `per_node` values per node in each
// array (1: nodes; kGauss: Gauss points by segment, from the owner of its first node). One
// reduction for all of them: crack growth collects every synchronized step.
class WholeArrays {
 public:
  void add(std::vector<double>& v, std::size_t per_node) { doubles_.push_back({&v, per_node}); }
  void add(std::vector<std::uint8_t>& v, std::size_t per_node) { flags_.push_back({&v, per_node}); }
  void run(const Comm& comm, const std::vector<unsigned char>& owned) {
    std::size_t n = 0;
    for (const auto& [v, per] : doubles_) n += v->size();
    for (const auto& [v, per] : flags_) n += v->size();
    std::vector<double> buf(n, 0.0);
    std::size_t at = 0;
    const auto pack = [&](const auto& list) {
      for (const auto& [v, per] : list) {
        for (std::size_t i = 0; i < v->size(); ++i)
          if (owned[i / per]) buf[at + i] = double((*v)[i]);
        at += v->size();
      }
    };
    pack(doubles_), pack(flags_);
    comm.sum(buf.data(), int(buf.size()));
    at = 0;
    for (const auto& [v, per] : doubles_) {
      std::copy(buf.begin() + long(at), buf.begin() + long(at + v->size()), v->begin());
      at += v->size();
    }
    for (const auto& [v, per] : flags_) {
      for (std::size_t i = 0; i < v->size(); ++i) (*v)[i] = std::uint8_t(buf[at + i]);
      at += v->size();
    }
  }

 private:
  std::vector<std::pair<std::vector<double>*, std::size_t>> doubles_;
  std::vector<std::pair<std::vector<std::uint8_t>*, std::size_t>> flags_;
};

// The rank owning each node of c: the block holding its reference point's cell.
std::vector<int> node_owners(const Grid& g, const CohesiveInterface& c, const std::vector<CellBlock>& blocks) {
  std::vector<int> owner(c.num_nodes(), 0);
  for (std::size_t k = 0; k < c.num_nodes(); ++k) {
    const int cx = cell_x(g, c.x0[k]), cy = cell_y(g, c.y0[k]);
    for (std::size_t q = 0; q < blocks.size(); ++q) {
      const CellBlock& b = blocks[q];
      if (cx >= b.c0 && cx < b.c1 && cy >= b.r0 && cy < b.r1) owner[k] = int(q);
    }
  }
  return owner;
}

bool knows_node(const Grid& g, const CohesiveInterface& c, const std::vector<int>& owner,
                const std::vector<CellBlock>& blocks, int q, std::size_t k, int cells) {
  return owner[k] == q || near_block(blocks[std::size_t(q)], cell_x(g, c.x0[k]), cell_y(g, c.y0[k]), cells);
}

}  // namespace

long interface_nodes_sent(const State& s, const std::vector<CellBlock>& blocks, int rank) {
  long sent = 0;
  for (const CohesiveInterface& c : s.interfaces) {
    const std::vector<int> owner = node_owners(s.grid, c, blocks);
    for (std::size_t k = 0; k < c.num_nodes(); ++k)
      if (owner[k] == rank)
        for (int q = 0; q < int(blocks.size()); ++q)
          sent += q != rank && knows_node(s.grid, c, owner, blocks, q, k, kKnownCells);
  }
  return sent;
}

void distribute_interfaces(State& s) {
  Halo& h = halo_of(s);
  const int me = h.comm.rank();
  h.links.assign(s.interfaces.size(), {});
  h.owned_nodes = 0.0;
  const int known = h.reaches.empty() ? 1 + h.face_cells : kKnownCells;
  for (std::size_t ic = 0; ic < s.interfaces.size(); ++ic) {
    CohesiveInterface& c = s.interfaces[ic];
    const std::size_t n = c.num_nodes();
    const std::vector<int> owner = node_owners(s.grid, c, h.blocks);
    auto knows = [&](int q, std::size_t k) { return knows_node(s.grid, c, owner, h.blocks, q, k, known); };
    c.rank_owned.assign(n, 0);
    c.rank_known.assign(n, 0);
    for (std::size_t k = 0; k < n; ++k) {
      c.rank_owned[k] = owner[k] == me;
      c.rank_known[k] = knows(me, k);
      h.owned_nodes += c.rank_owned[k];
    }
    // Segments reach one node on: an owned node's neighbours must be known (one grid: the reach
    // is laid wide enough, lay_reach and longest_segment_cells; nested levels: refused here).
    for (std::size_t k = 0; k < n; ++k) {
      if (!c.rank_owned[k]) continue;
      const std::size_t next = c.closed ? (k + 1) % n : std::min(k + 1, n - 1);
      const std::size_t prev = c.closed ? (k + n - 1) % n : (k > 0 ? k - 1 : 0);
      for (const std::size_t j : {prev, next})
        if (!c.rank_known[j])
          throw InputError(fmt::format(
              "interface {} (input order): segment from ({:.6g}, {:.6g}) to ({:.6g}, {:.6g}) m is longer than "
              "a distributed run on nested levels allows ({} cells of {:.6g} m between a node and its "
              "neighbour); refine the interface's segments or run on one process",
              ic, c.x0[k], c.y0[k], c.x0[j], c.y0[j], known, h.cell));
    }
    Halo::InterfaceLinks& L = h.links[ic];
    L.send.assign(h.peers.size(), {});
    L.recv.assign(h.peers.size(), {});
    for (std::size_t p = 0; p < h.peers.size(); ++p) {
      const int q = h.peers[p].rank;
      for (std::size_t k = 0; k < n; ++k) {
        if (owner[k] == me && knows(q, k)) L.send[p].push_back(std::uint32_t(k));
        if (owner[k] == q && c.rank_known[k]) L.recv[p].push_back(std::uint32_t(k));
      }
    }
  }
  // Bonded ties act on each copy of a node alike (after the halo sums): a rank ties the nodes
  // of its reach.
  const std::size_t nx = std::size_t(s.grid.nodes_x());
  for (BondedTie& b : s.bonded)
    std::erase_if(b.nodes, [&](std::size_t node) {
      return !h.reach.contains(int(node % nx), int(node / nx));
    });
}

void Halo::sync_interface_nodes(State& s, CohesiveInterface& c, std::initializer_list<InterfaceArray> arrays) {
  Halo& h = *this;
  const std::size_t ic = std::size_t(&c - s.interfaces.data());
  const Halo::InterfaceLinks& L = h.links[ic];
  const std::size_t A = arrays.size();
  for (std::size_t p = 0; p < h.peers.size(); ++p) {
    PeerBuffers& b = h.buffers[p];
    b.send.resize(L.send[p].size() * A * sizeof(double));
    b.recv.resize(L.recv[p].size() * A * sizeof(double));
    double* out = reinterpret_cast<double*>(b.send.data());
    for (const std::uint32_t k : L.send[p])
      for (const InterfaceArray a : arrays) *out++ = (c.*a)[k];
  }
  h.exchange(true);
  for (std::size_t p = 0; p < h.peers.size(); ++p) {
    const unsigned char* in = h.buffers[p].recv.data();
    for (const std::uint32_t k : L.recv[p])
      for (const InterfaceArray a : arrays) {
        std::memcpy(&(c.*a)[k], in, sizeof(double));
        in += sizeof(double);
      }
  }
}

void collect_interface_state(State& s) {
  if (!s.halo) return;
  const Comm& comm = halo_of(s).comm;
  for (CohesiveInterface& c : s.interfaces) {
    WholeArrays arrays;
    // Every array InterfaceArrays marks kGathered: a node's values from its owner (arrays of
    // another length, not in use on this interface, stay as they are), Gauss points by segment,
    // each from the owner of its first node.
    const std::size_t G = std::size_t(CohesiveInterface::kGauss);
    for_each_interface_array([&](const auto& a) {
      if (!a.has(kGathered)) return;
      using T = typename std::decay_t<decltype(a)>::value_type;
      if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::uint8_t>) {
        auto& v = c.*a.member;
        if (a.extent == InterfaceExtent::gauss)
          arrays.add(v, G);
        else if (a.extent == InterfaceExtent::node && v.size() == c.num_nodes())
          arrays.add(v, 1);
      } else {
        throw std::logic_error(std::string("collect_interface_state: no rule to gather ") + a.name);
      }
    });
    arrays.run(comm, c.rank_owned);
  }
}

int longest_segment_cells(const State& s) {
  int most = 0;
  for (const CohesiveInterface& c : s.interfaces) {
    const std::size_t n = c.num_nodes();
    for (std::size_t k = 0; k + 1 < n + (c.closed ? 1 : 0); ++k) {
      const std::size_t j = (k + 1) % n;
      most = std::max({most, std::abs(cell_x(s.grid, c.x0[k]) - cell_x(s.grid, c.x0[j])),
                       std::abs(cell_y(s.grid, c.y0[k]) - cell_y(s.grid, c.y0[j]))});
    }
  }
  return most;
}

double face_travel(const State& s) {
  // By the owners (every node has one; its ghosts' copies may lag a step). Chebyshev, in cells of
  // the finest size (graded grids: as the migration counts).
  const double cell = halo_of(s).cell;
  double most = 0.0;
  for (const CohesiveInterface& c : s.interfaces)
    for (std::size_t k = 0; k < c.num_nodes(); ++k)
      if (c.owns(k))
        for (const double u : {c.ux_up[k], c.uy_up[k], c.ux_lo[k], c.uy_lo[k]})
          if (std::fabs(u) > most) most = std::fabs(u);  // a NaN stays out (the step diagnoses it)
  return most / cell;
}

void Halo::check_faces_in_reach(State& s) {
  Halo& h = *this;
  for (std::size_t ic = 0; ic < s.interfaces.size(); ++ic) {
    const CohesiveInterface& c = s.interfaces[ic];
    for (std::size_t k = 0; k < c.num_nodes(); ++k) {
      if (!c.knows(k)) continue;
      for (const int side : {0, 1}) {
        const double x = c.x0[k] + (side ? c.ux_lo[k] : c.ux_up[k]);
        const double y = c.y0[k] + (side ? c.uy_lo[k] : c.uy_up[k]);
        const int i = cell_x(s.grid, x), j = cell_y(s.grid, y);
        const bool injected = fault_due(FaultSite::face_out_of_reach, s.step);  // tests
        if (!injected && h.reach.contains(i, j) && h.reach.contains(i + 1, j + 1)) continue;
        if (h.failure.empty())
          h.failure = fmt::format(
              "interface {} (input order) node {} at (x, y) = ({:.6g}, {:.6g}) m: its {} face moved to ({:.6g}, "
              "{:.6g}) m, past rank {}'s halo ({}), step {}, t = {:.6g} s",
              ic, k, c.x0[k], c.y0[k], side ? "lower" : "upper", x, y, h.comm.rank(),
              h.reaches.empty() ? fmt::format("its reach holds faces that moved less than {} from where they were "
                                              "drawn, and widens before they reach that",
                                              h.face_cells == 1 ? std::string("a cell")
                                                                : fmt::format("{} cells", h.face_cells))
                                : "on nested levels a face may move up to a cell on a distributed run",
              s.step, s.time);
        return;
      }
    }
  }
}

void collect_crack_times(State& s) {
  if (!s.halo) return;
  for (CohesiveInterface& c : s.interfaces) {
    WholeArrays arrays;
    for (auto* v : {&c.node_crack_time, &c.node_rupture_time, &c.node_peak_slip_rate, &c.ux_up,
                    &c.uy_up, &c.ux_lo, &c.uy_lo})
      arrays.add(*v, 1);
    arrays.run(halo_of(s).comm, c.rank_owned);
  }
}

void collect_crack_fronts(RunState& r) {
  for (State& l : r.levels) {
    if (!l.halo) continue;
    const std::size_t G = std::size_t(CohesiveInterface::kGauss);
    for (CohesiveInterface& c : l.interfaces) {
      WholeArrays arrays;
      arrays.add(c.gp_dn, G), arrays.add(c.gp_dt, G), arrays.add(c.gp_separated, G);
      arrays.run(halo_of(l).comm, c.rank_owned);
    }
  }
}

void collect_interface_state(RunState& r) {
  for (State& l : r.levels)
    if (!l.interfaces.empty()) collect_interface_state(l);
}

void collect_crack_times(RunState& r) {
  for (State& l : r.levels)
    if (!l.interfaces.empty()) collect_crack_times(l);
}

InterfaceShapes interface_shapes(const State& s) {
  InterfaceShapes shapes;
  for (const CohesiveInterface& c : s.interfaces) {
    shapes.nodes.push_back(c.num_nodes());
    shapes.tie_lines.push_back(c.spec.bonded_lines);
  }
  for (const BondedTie& b : s.bonded)
    shapes.tie_nodes.push_back(b.nodes), shapes.tie_fields.push_back({b.upper_field, b.lower_field});
  return shapes;
}

void follow_grown_interfaces(State& s, const InterfaceShapes& before) {
  if (!s.halo) return;
  Halo& h = halo_of(s);
  const auto same_lines = [](const std::vector<Polyline>& a, const std::vector<Polyline>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
    return true;
  };
  bool changed = s.interfaces.size() != before.nodes.size();
  h.all_bonded.resize(s.bonded.size());
  for (std::size_t i = 0; i < s.bonded.size(); ++i) {
    bool relaid = i >= before.tie_nodes.size() || s.bonded[i].nodes != before.tie_nodes[i] ||
                  before.tie_fields[i] != std::array<int, 2>{s.bonded[i].upper_field, s.bonded[i].lower_field};
    if (i < s.interfaces.size() && i < before.nodes.size())
      relaid = relaid || s.interfaces[i].num_nodes() != before.nodes[i] ||
               !same_lines(s.interfaces[i].spec.bonded_lines, before.tie_lines[i]);
    if (!relaid) continue;
    h.all_bonded[i] = s.bonded[i];  // growth laid it on every node
    changed = true;
  }
  if (!changed) return;
  s.bonded = h.all_bonded;
  distribute_interfaces(s);
  s.windows_checked_step = -2;  // re-fit the windows (flipped particles' fields)
}

double interface_work(const RunState& r, std::size_t k) { return sum_over_ranks(r, r.interface(k).work); }

}  // namespace rupture
