// rupture/output/stations.cpp
#include "output/stations.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "output/interface_csv.hpp"
#include "parallel/halo.hpp"
#include "solver/run_state.hpp"
#include "geometry/shape.hpp"

namespace rupture {

void NearestParticle::visit(double px, double py, std::uint32_t pid) {
  const double d = std::hypot(px - x, py - y);
  if (d < best || (d == best && pid < id)) best = d, id = pid, best_x = px, best_y = py;
  if (d <= radius) near.push_back({px, py, pid});
}

std::vector<double> linear_fit_weights(const std::vector<NearestParticle::Point>& points, double x0,
                                       double y0) {
  // Rows r_k = [1, dx_k / L, dy_k / L] (L the points' reach: a scale, for the conditioning);
  // the fit's value at the point is e_1 . (R^T R)^-1 R^T q, so w_k = r_k . z with (R^T R) z = e_1.
  if (points.size() < 3) return {};
  double L = 0.0;
  for (const auto& p : points) L = std::max(L, std::hypot(p.x - x0, p.y - y0));
  if (!(L > 0.0)) return {};
  double N[3][3] = {};
  for (const auto& p : points) {
    const double r[3] = {1.0, (p.x - x0) / L, (p.y - y0) / L};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) N[i][j] += r[i] * r[j];
  }
  // z = first column of N^-1 (cofactors over the determinant).
  const double c00 = N[1][1] * N[2][2] - N[1][2] * N[2][1];
  const double c01 = N[1][2] * N[2][0] - N[1][0] * N[2][2];
  const double c02 = N[1][0] * N[2][1] - N[1][1] * N[2][0];
  const double det = N[0][0] * c00 + N[0][1] * c01 + N[0][2] * c02;
  // On one line the spread in one direction vanishes: det ~ 0 against n^3 for a spread set.
  const double n = double(points.size());
  if (!(std::fabs(det) > 1e-9 * n * n * n)) return {};
  const double z[3] = {c00 / det, c01 / det, c02 / det};
  std::vector<double> w;
  w.reserve(points.size());
  for (const auto& p : points) w.push_back(z[0] + z[1] * (p.x - x0) / L + z[2] * (p.y - y0) / L);
  return w;
}

std::vector<NearestParticle> station_visitors(const Case& c, const RunState& s) {
  std::vector<NearestParticle> out;
  const Grid& g = s.run_grid();
  for (const StationSpec& st : c.stations) {
    NearestParticle n{st.x, st.y};
    if (st.interface < 0 && st.interpolated)
      n.radius = std::max(g.x.width(g.x.cell_of(st.x)), g.y.width(g.y.cell_of(st.y)));
    out.push_back(n);
  }
  return out;
}

namespace {

// An interpolated station's particles: those within its radius in the body holding the
// nearest one (a point of another body across an interface would mix the two sides), and
// their fit's weights; none (the nearest particle alone) where they do not span the plane.
void fit_probe(const Case& c, const NearestParticle& n, StationProbe& p) {
  const BodySpec* body = nullptr;
  for (const BodySpec& b : c.bodies)
    if (contains(b.region, n.best_x, n.best_y)) {
      body = &b;
      break;
    }
  std::vector<NearestParticle::Point> pts;
  for (const NearestParticle::Point& q : n.near)
    if (!body || contains(body->region, q.x, q.y)) pts.push_back(q);
  // The same set whatever order the particles were visited in (a distributed run's).
  std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  const std::vector<double> w = linear_fit_weights(pts, n.x, n.y);
  if (w.empty()) return;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    p.fit_ids.push_back(pts[k].id);
    p.fit_weights.push_back(w[k]);
    p.fit_slots.push_back(0);
  }
}

}  // namespace

std::vector<StationProbe> make_probes(const Case& c, RunState& s,
                                      const std::vector<NearestParticle>* visited) {
  const std::vector<StationSpec>& specs = c.stations;
  std::vector<NearestParticle> own;
  if (!visited) {
    own = station_visitors(c, s);
    const Particles& P = all_particles(s);
    for (NearestParticle& n : own)
      for (std::size_t q = 0; q < P.size(); ++q) n.visit(P.x[q], P.y[q], P.id[q]);
    visited = &own;
  }
  std::vector<StationProbe> out;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const StationSpec& st = specs[k];
    StationProbe p;
    p.interface = st.interface;
    if (st.interface >= 0) {
      const CohesiveInterface& fault = s.interface(std::size_t(st.interface));
      const double arc = project(fault.spec.geometry(), st.x, st.y).s;
      // The node pair around the arc length (open line; a closed one ends on node 0).
      const std::size_t n = fault.num_nodes();
      std::size_t a = 0;
      while (a + 1 < n && fault.s0[a + 1] <= arc) ++a;
      p.a = a;
      p.b = a + 1 < n ? a + 1 : (fault.closed ? 0 : a);
      const double len = p.b == p.a ? 1.0 : (p.b == 0 ? fault.length() : fault.s0[p.b]) - fault.s0[p.a];
      p.f = p.b == p.a ? 0.0 : std::clamp((arc - fault.s0[p.a]) / len, 0.0, 1.0);
      p.state = std::holds_alternative<RateStateFriction>(fault.spec.law);
    } else {
      const NearestParticle& n = (*visited)[k];
      p.particle_id = n.id;
      p.slot = 0;  // found at the first read
      if (st.interpolated) fit_probe(c, n, p);
    }
    out.push_back(p);
  }
  return out;
}

namespace {

// The index of particle `id`, kept in `slot` (re-found after a sort); P.size() when this
// rank does not hold it.
std::size_t find_particle(const Particles& P, std::uint32_t id, std::size_t& slot) {
  if (slot >= P.size() || P.id[slot] != id)
    slot = std::size_t(std::find(P.id.begin(), P.id.end(), id) - P.id.begin());
  return slot;
}

// A body station's x, y, vx, vy: its particle's, or its fit's (the particles this rank holds:
// a distributed run sums the ranks' shares).
void read_body(const Particles& P, StationProbe& p, double* row) {
  if (p.fit_ids.empty()) {
    const std::size_t q = find_particle(P, p.particle_id, p.slot);
    if (q >= P.size()) return;  // another rank's
    row[0] = P.x[q], row[1] = P.y[q], row[2] = P.vx[q], row[3] = P.vy[q];
    return;
  }
  for (std::size_t k = 0; k < p.fit_ids.size(); ++k) {
    const std::size_t q = find_particle(P, p.fit_ids[k], p.fit_slots[k]);
    if (q >= P.size()) continue;
    const double w = p.fit_weights[k];
    row[0] += w * P.x[q], row[1] += w * P.y[q], row[2] += w * P.vx[q], row[3] += w * P.vy[q];
  }
}

double jump_rate(const CohesiveInterface& c, std::size_t k, double dt) {
  return dt > 0 ? c.last_increment_t[k] / dt : 0.0;
}

// A distributed run (parallel/halo.hpp): each node's values from the rank owning it, each body
// station's particle from the rank holding it, added over the ranks (zeros elsewhere), so every
// rank records the one-process rows.
void sample_distributed(RunState& s, std::vector<StationProbe>& probes,
                        std::vector<StationSeries>& series) {
  constexpr std::size_t kV = kFaultColumns - 1;  // per node: the fault row without the time
  std::vector<double> v(probes.size() * 2 * kV, 0.0);
  for (std::size_t i = 0; i < probes.size(); ++i) {
    StationProbe& p = probes[i];
    double* out = v.data() + i * 2 * kV;
    if (p.interface >= 0) {
      const CohesiveInterface& c = s.interface(std::size_t(p.interface));
      const std::size_t nodes[2] = {p.a, p.b};
      for (int e = 0; e < 2; ++e) {
        const std::size_t k = nodes[e];
        if (!c.owns(k)) continue;
        const CohesiveTraction t = node_traction(c, k);
        const double row[kV] = {c.jump_tangential(k), c.node_slip_rate[k], c.jump_normal(k),
                                t.tangential,         t.normal,            jump_rate(c, k, s.dt),
                                node_state(c, k)};
        std::copy(row, row + kV, out + e * kV);
      }
      continue;
    }
    read_body(all_particles(s), p, out);  // zeros where another rank holds the particles
  }
  const Comm& comm = halo_of(s).comm;
  comm.sum(v.data(), int(v.size()));
  series.resize(probes.size());
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const double* in = v.data() + i * 2 * kV;
    std::vector<double>& r = series[i].rows;
    if (probes[i].interface >= 0) {
      const double f = probes[i].f;
      r.push_back(s.time);
      for (std::size_t j = 0; j < kV; ++j) r.push_back((1.0 - f) * in[j] + f * in[kV + j]);
    } else {
      r.insert(r.end(), {s.time, in[0], in[1], in[2], in[3]});
    }
  }
}

}  // namespace

void sample_stations(RunState& s, std::vector<StationProbe>& probes,
                     std::vector<StationSeries>& series) {
  if (s.halo && halo_of(s).comm.distributed()) return sample_distributed(s, probes, series);
  series.resize(probes.size());
  for (std::size_t i = 0; i < probes.size(); ++i) {
    StationProbe& p = probes[i];
    std::vector<double>& r = series[i].rows;
    if (p.interface >= 0) {
      const CohesiveInterface& c = s.interface(std::size_t(p.interface));
      auto mix = [&](double va, double vb) { return (1.0 - p.f) * va + p.f * vb; };
      const CohesiveTraction ta = node_traction(c, p.a), tb = node_traction(c, p.b);
      const double row[kFaultColumns] = {s.time,
                                         mix(c.jump_tangential(p.a), c.jump_tangential(p.b)),
                                         mix(c.node_slip_rate[p.a], c.node_slip_rate[p.b]),
                                         mix(c.jump_normal(p.a), c.jump_normal(p.b)),
                                         mix(ta.tangential, tb.tangential),
                                         mix(ta.normal, tb.normal),
                                         mix(jump_rate(c, p.a, s.dt), jump_rate(c, p.b, s.dt)),
                                         mix(node_state(c, p.a), node_state(c, p.b))};
      r.insert(r.end(), row, row + kFaultColumns);
    } else {
      double row[kBodyColumns] = {s.time, 0.0, 0.0, 0.0, 0.0};
      read_body(all_particles(s), p, row + 1);
      r.insert(r.end(), row, row + kBodyColumns);
    }
  }
}

void write_stations(const std::string& dir, const std::vector<StationSpec>& specs,
                    const std::vector<StationProbe>& probes,
                    const std::vector<StationSeries>& series) {
  if (specs.empty()) return;
  std::filesystem::create_directories(dir + "/stations");
  for (std::size_t i = 0; i < specs.size() && i < series.size(); ++i) {
    const bool fault = probes[i].interface >= 0;
    const std::size_t cols = fault ? kFaultColumns : kBodyColumns;
    // A fault file's last column, the state, only where the fault has one (rate and state).
    const std::size_t written = fault && !probes[i].state ? cols - 1 : cols;
    std::string out = !fault ? "time,x,y,vx,vy,ux,uy"
                             : "time,slip,slip_rate,opening,shear_traction,normal_traction,jump_rate";
    out += fault && probes[i].state ? ",state\n" : "\n";
    const std::vector<double>& r = series[i].rows;
    for (std::size_t k = 0; k + cols <= r.size(); k += cols) {
      for (std::size_t j = 0; j < written; ++j) {
        if (j > 0) out += ',';
        out += fmt::format("{:.9e}", r[k + j]);
      }
      if (!fault)  // the displacement since the first sample (t = 0)
        out += fmt::format(",{:.9e},{:.9e}", r[k + 1] - r[1], r[k + 2] - r[2]);
      out += '\n';
    }
    write_file_atomic(dir + "/stations/" + specs[i].name + ".csv", out);
  }
}

}  // namespace rupture
