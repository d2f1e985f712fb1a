// rupture/solver/load_step.cpp
// Loads in the time step (solver/load_step.hpp). Per-step loops use preallocated arrays only.
#include "solver/load_step.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/errors.hpp"
#include "solver/rank_exchange.hpp"

namespace rupture {
namespace {

// Calls visit(node, weight) for the nodes of particle p with a nonzero GIMP weight (E3); node
// is the grid index within the particle's field plus the field offset.
template <class Visit>
inline void for_each_weight(const State& s, std::size_t p, Visit&& visit) {
  const Particles& P = s.particles;
  Stencil1D sx, sy;
  stencil(s.grid.x, P.x[p], P.half_x[p], sx);
  stencil(s.grid.y, P.y[p], P.half_y[p], sy);
  const int f = P.field[p];
  for (int b = 0; b < 3; ++b)
    for (int a = 0; a < 3; ++a) {
      const double w = sx.s[a] * sy.s[b];
      if (w > 0.0) visit(s.fields.index(f, sx.first + a, sy.first + b), w);
    }
}

}  // namespace

void set_up_loads(State& s, const Loads& loads, double cell_size, const Particles* near) {
  LoadState& L = s.loads;
  L.spec = loads;
  if (loads.empty()) return;
  for (const TractionLoad& t : loads.tractions)
    L.patches.push_back(find_traction_patch(t, near ? *near : s.particles, cell_size));
  for (const VelocityRegion& r : loads.velocity_regions) {
    L.region_ids.push_back(region_particles(r, near ? *near : s.particles));
    if (L.region_ids.back().empty())
      throw InputError(fmt::format(
          "input keys 'loads.{0}.min', 'loads.{0}.max' = [{1:g}, {2:g}]..[{3:g}, {4:g}]: the box "
          "holds no particle (of the bodies it names); a velocity region must hold material",
          r.name, r.min[0], r.min[1], r.max[0], r.max[1]));
  }
  for (const PointForceLoad& f : loads.point_forces)
    L.spreads.push_back(find_point_spread(f, near ? *near : s.particles));
  L.spread_index.resize(L.spreads.size());
  for (std::size_t k = 0; k < L.spreads.size(); ++k) L.spread_index[k].resize(L.spreads[k].ids.size());
  L.patch_index.resize(L.patches.size());
  for (std::size_t k = 0; k < L.patches.size(); ++k) L.patch_index[k].resize(L.patches[k].ids.size());
  L.region_index.resize(L.region_ids.size());
  for (std::size_t k = 0; k < L.region_ids.size(); ++k) L.region_index[k].resize(L.region_ids[k].size());
  const std::size_t grid_nodes = s.fields.mass.size();
  L.accel_x.resize(std::size_t(s.fields.num_fields));
  L.accel_y.resize(std::size_t(s.fields.num_fields));
  if (L.has_forces()) {
    L.ext_fx.assign(grid_nodes, 0.0);
    L.ext_fy.assign(grid_nodes, 0.0);
  }
  if (!loads.velocity_regions.empty()) {
    L.node_stamp.assign(grid_nodes, 0);
    std::size_t most = 0;
    for (const auto& ids : L.region_ids) most += 9 * ids.size();
    L.region_nodes.reserve(most);
  }
}

namespace {

// A node the bonded tie makes one continuum (solver/cohesive_step.hpp: both fields' copies hold
// the summed mass and momentum, hence one velocity) is prescribed on both copies when the region
// reaches either: prescribing one copy alone leaves the other, the same material point, moving
// freely, and the tie then sums a prescribed and a free momentum each step (seen as an energy
// blow-up beside a tie under a load at the mid-span). The impulse acts on the summed mass once,
// so its work is counted on one copy.
void both_copies_of_tied_nodes(State& s, long stamp) {
  LoadState& L = s.loads;
  const GridFields& G = s.fields;
  for (const BondedTie& b : s.bonded)
    for (const std::size_t n : b.nodes) {
      const std::size_t iu = G.index(b.upper_field, n), il = G.index(b.lower_field, n);
      const bool up = L.node_stamp[iu] == stamp, lo = L.node_stamp[il] == stamp;
      if (up == lo) {
        if (!up) continue;
        for (LoadState::RegionNode& e : L.region_nodes)
          if (e.node == il) e.work = false;
        continue;
      }
      const std::size_t from = up ? iu : il, to = up ? il : iu;
      int region = 0;
      for (const LoadState::RegionNode& e : L.region_nodes)
        if (e.node == from) region = e.region;
      L.node_stamp[to] = stamp;
      L.region_nodes.push_back({to, region, false});
    }
}

}  // namespace

void prepare_loads(State& s) {
  LoadState& L = s.loads;
  if (L.spec.tractions.empty() && L.spec.velocity_regions.empty() && L.spec.point_forces.empty())
    return;
  const Particles& P = s.particles;
  if (L.indexed_sort != s.plan.sorted_step) {
    // Indexed by id: as long as the largest id held (a distributed rank's ids are some of the
    // case's, and migration brings others).
    std::uint32_t top = 0;
    for (std::size_t p = 0; p < P.size(); ++p) top = std::max(top, P.id[p] + 1);
    if (L.slot_of_id.size() < top) L.slot_of_id.resize(top, LoadState::kAbsent);
    for (std::size_t p = 0; p < P.size(); ++p) L.slot_of_id[P.id[p]] = std::uint32_t(p);
    // A distributed run holds some of the ids: an entry left from an earlier sort points at
    // another particle (or past the end) and marks the id absent.
    auto slot = [&](std::uint32_t id) {
      const std::uint32_t p = id < L.slot_of_id.size() ? L.slot_of_id[id] : LoadState::kAbsent;
      return p < P.size() && P.id[p] == id ? p : LoadState::kAbsent;
    };
    for (std::size_t k = 0; k < L.patches.size(); ++k)
      for (std::size_t j = 0; j < L.patches[k].ids.size(); ++j)
        L.patch_index[k][j] = slot(L.patches[k].ids[j]);
    for (std::size_t k = 0; k < L.spreads.size(); ++k)
      for (std::size_t j = 0; j < L.spreads[k].ids.size(); ++j)
        L.spread_index[k][j] = slot(L.spreads[k].ids[j]);
    for (std::size_t k = 0; k < L.region_ids.size(); ++k) {  // the region particles held here
      L.region_index[k].clear();  // keeps its capacity (the region's ids): no allocation
      for (std::size_t j = 0; j < L.region_ids[k].size(); ++j)
        if (const std::uint32_t p = slot(L.region_ids[k][j]); p != LoadState::kAbsent) L.region_index[k].push_back(p);
    }
    L.indexed_sort = s.plan.sorted_step;
  }
  // Stamps per field node: re-made when the windows were re-fitted (solver/field_windows.hpp).
  if (L.node_stamp.size() != s.fields.size()) L.node_stamp.assign(s.fields.size(), 0);
  const bool distributed = s.halo && !L.region_index.empty();
  if (distributed) {  // the marks of the last step's list back to none
    if (L.node_region.size() != s.fields.size())
      L.node_region.assign(s.fields.size(), -1);
    else
      for (const LoadState::RegionNode& e : L.region_nodes) L.node_region[e.node] = -1;
  }
  // Nodes the region particles touch at t^n, each listed once (in input and id order).
  L.region_nodes.clear();  // keeps its capacity: no allocation
  const long stamp = s.step + 1;
  for (std::size_t r = 0; r < L.region_index.size(); ++r)
    for (const std::uint32_t p : L.region_index[r])
      for_each_weight(s, p, [&](std::size_t i, double) {
        if (L.node_stamp[i] == stamp) return;
        L.node_stamp[i] = stamp;
        L.region_nodes.push_back({i, int(r)});
        if (distributed) L.node_region[i] = int(r);
      });
  if (distributed) {
    // Distributed: a halo node is listed on every rank holding it, with the lowest region any
    // rank's particles give it (the one that lists it first on one process).
    halo_lowest_region(s, L.node_region, L.region_changed);
    for (const std::size_t e : L.region_changed) {
      if (L.node_stamp[e] != stamp) {
        L.node_stamp[e] = stamp;
        L.region_nodes.push_back({e, L.node_region[e]});
        continue;
      }
      for (LoadState::RegionNode& n : L.region_nodes)
        if (n.node == e) n.region = L.node_region[e];
    }
  }
  both_copies_of_tied_nodes(s, stamp);
}

void add_external_forces(State& s) {
  LoadState& L = s.loads;
  if (!L.has_forces()) return;
  const Particles& P = s.particles;
  const double t = s.time;
  L.ext_fx.assign(s.fields.size(), 0.0);  // same size as the bands: no allocation
  L.ext_fy.assign(s.fields.size(), 0.0);
  // Body forces: f_p = m_p g(t), per field (one field per body).
  if (!L.spec.body_forces.empty()) {
    std::fill(L.accel_x.begin(), L.accel_x.end(), 0.0);
    std::fill(L.accel_y.begin(), L.accel_y.end(), 0.0);
    for (const BodyForceLoad& b : L.spec.body_forces) {
      const double f = b.factor(t);
      for (int field = 0; field < s.fields.num_fields; ++field) {
        if (!b.fields.empty() && std::find(b.fields.begin(), b.fields.end(), field) == b.fields.end())
          continue;
        L.accel_x[std::size_t(field)] += f * b.acceleration[0];
        L.accel_y[std::size_t(field)] += f * b.acceleration[1];
      }
    }
    // Strips of one colour touch disjoint nodes (ScatterPlan): no race.
    const ScatterPlan& plan = s.plan;
    for (int colour = 0; colour < 2; ++colour) {
#pragma omp parallel for schedule(dynamic, 1)
      for (int strip = colour; strip < plan.num_strips; strip += 2)
        for (std::size_t p = plan.strip_begin[std::size_t(strip)];
             p < plan.strip_begin[std::size_t(strip) + 1]; ++p) {
          const double gx = L.accel_x[P.field[p]], gy = L.accel_y[P.field[p]];
          if (gx == 0.0 && gy == 0.0) continue;
          const double fx = P.mass[p] * gx, fy = P.mass[p] * gy;
          for_each_weight(s, p, [&](std::size_t i, double w) {
            L.ext_fx[i] += w * fx;
            L.ext_fy[i] += w * fy;
          });
        }
    }
  }
  // Tractions: f_p = traction(t) length_p.
  for (std::size_t k = 0; k < L.patches.size(); ++k) {
    const TractionLoad& load = L.spec.tractions[k];
    const TractionPatch& patch = L.patches[k];
    double tx, ty;
    patch_traction(load, patch, t, tx, ty);
    for (std::size_t j = 0; j < patch.ids.size(); ++j) {
      const double len = patch.length[j];
      if (L.patch_index[k][j] == LoadState::kAbsent) continue;  // another rank's particle
      for_each_weight(s, L.patch_index[k][j], [&](std::size_t i, double w) {
        L.ext_fx[i] += w * tx * len;
        L.ext_fy[i] += w * ty * len;
      });
    }
  }
  // Point forces: f_p = F factor(t) w_p.
  for (std::size_t k = 0; k < L.spreads.size(); ++k) {
    const PointForceLoad& load = L.spec.point_forces[k];
    const double f = load.factor(t);
    const PointSpread& spread = L.spreads[k];
    for (std::size_t j = 0; j < spread.ids.size(); ++j) {
      if (L.spread_index[k][j] == LoadState::kAbsent) continue;  // another rank's particle
      const double fx = f * load.force[0] * spread.weight[j], fy = f * load.force[1] * spread.weight[j];
      for_each_weight(s, L.spread_index[k][j], [&](std::size_t i, double w) {
        L.ext_fx[i] += w * fx;
        L.ext_fy[i] += w * fy;
      });
    }
  }
  GridFields& G = s.fields;
  const long n = long(G.force_x.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    G.force_x[i] += L.ext_fx[i];
    G.force_y[i] += L.ext_fy[i];
  }
}

namespace {

// The field and the grid node (i + j nodes_x) of element e of the fields.
int field_of(const GridFields& G, std::size_t e) {
  return int(std::upper_bound(G.start.begin(), G.start.end(), e) - G.start.begin()) - 1;
}
std::size_t grid_node_of(const GridFields& G, std::size_t e) {
  const std::size_t f = std::size_t(field_of(G, e)), local = e - G.start[f];
  const std::size_t cols = std::size_t(G.cols[f]);
  return std::size_t(G.col0[f]) + local % cols + (std::size_t(G.row0[f]) + local / cols) * G.nodes_x;
}

}  // namespace

void apply_velocity_regions(State& s) {
  LoadState& L = s.loads;
  if (L.region_nodes.empty()) return;
  GridFields& G = s.fields;
  const double t0 = s.time, t1 = s.time + s.dt;
  for (const LoadState::RegionNode& e : L.region_nodes) {
    const double m = G.mass[e.node];
    if (m <= s.mass_floor) continue;
    const VelocityRegion& r = L.spec.velocity_regions[std::size_t(e.region)];
    const double dx = r.direction[0], dy = r.direction[1];
    const double v0 = r.velocity(t0), v1 = r.velocity(t1);
    const double jump = v1 - (G.vel_x[e.node] * dx + G.vel_y[e.node] * dy);
    // Impulse m jump along d, acting at the mean prescribed speed (as apply_velocity_bcs, E14);
    // distributed: a shared node's work counted once.
    if (e.work && (!s.halo || counts_node(s, field_of(G, e.node), grid_node_of(G, e.node))))
      s.external_work += m * jump * 0.5 * (v0 + v1);
    G.vel_x[e.node] += jump * dx;
    G.vel_y[e.node] += jump * dy;
    G.dvel_x[e.node] += jump * dx;
    G.dvel_y[e.node] += jump * dy;
  }
}

void prescribe_region_velocity(State& s, double* gvx, double* gvy, double t) {
  LoadState& L = s.loads;
  for (const LoadState::RegionNode& e : L.region_nodes) {
    if (s.fields.mass[e.node] <= s.mass_floor) continue;
    const VelocityRegion& r = L.spec.velocity_regions[std::size_t(e.region)];
    const double jump = r.velocity(t) - (gvx[e.node] * r.direction[0] + gvy[e.node] * r.direction[1]);
    gvx[e.node] += jump * r.direction[0];
    gvy[e.node] += jump * r.direction[1];
  }
}

void external_force_work(State& s) {
  LoadState& L = s.loads;
  if (!L.has_forces()) return;
  const GridFields& G = s.fields;
  double w = 0.0;
  // Serial: the sum does not depend on the number of threads.
  for (std::size_t i = 0; i < L.ext_fx.size(); ++i) {
    if (L.ext_fx[i] == 0.0 && L.ext_fy[i] == 0.0) continue;
    const double m = G.mass[i];
    if (m <= s.mass_floor) continue;
    const double vx0 = G.mom_x[i] / m, vy0 = G.mom_y[i] / m;
    w += L.ext_fx[i] * (vx0 + G.vel_x[i]) + L.ext_fy[i] * (vy0 + G.vel_y[i]);
  }
  s.external_work += 0.5 * s.dt * w;
}

void set_region_particle_velocity(State& s) {
  LoadState& L = s.loads;
  Particles& P = s.particles;
  const double t1 = s.time + s.dt;
  for (std::size_t r = 0; r < L.region_index.size(); ++r) {
    const VelocityRegion& reg = L.spec.velocity_regions[r];
    const double v1 = reg.velocity(t1), dx = reg.direction[0], dy = reg.direction[1];
    for (const std::uint32_t p : L.region_index[r]) {
      const double u = P.vx[p] * dx + P.vy[p] * dy;
      s.external_work += P.mass[p] * (v1 - u) * 0.5 * (v1 + u);  // its kinetic energy change
      P.vx[p] += (v1 - u) * dx;
      P.vy[p] += (v1 - u) * dy;
    }
  }
}

}  // namespace rupture
