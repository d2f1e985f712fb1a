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

namespace rupture {

void NearestParticle::visit(double px, double py, std::uint32_t pid) {
  const double d = std::hypot(px - x, py - y);
  if (d < best || (d == best && pid < id)) best = d, id = pid;
}

std::vector<StationProbe> make_probes(const std::vector<StationSpec>& specs, RunState& s,
                                      const std::vector<std::uint32_t>* nearest) {
  std::vector<StationProbe> out;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const StationSpec& st = specs[k];
    StationProbe p;
    p.interface = st.interface;
    if (st.interface >= 0) {
      const CohesiveInterface& c = s.interface(std::size_t(st.interface));
      const double arc = project(c.spec.geometry(), st.x, st.y).s;
      // The node pair around the arc length (open line; a closed one ends on node 0).
      const std::size_t n = c.num_nodes();
      std::size_t a = 0;
      while (a + 1 < n && c.s0[a + 1] <= arc) ++a;
      p.a = a;
      p.b = a + 1 < n ? a + 1 : (c.closed ? 0 : a);
      const double len = p.b == p.a ? 1.0 : (p.b == 0 ? c.length() : c.s0[p.b]) - c.s0[p.a];
      p.f = p.b == p.a ? 0.0 : std::clamp((arc - c.s0[p.a]) / len, 0.0, 1.0);
      p.state = std::holds_alternative<RateStateFriction>(c.spec.law);
    } else if (nearest) {
      p.particle_id = (*nearest)[k];
      p.slot = 0;  // found at the first read
    } else {
      const Particles& P = all_particles(s);
      NearestParticle n{st.x, st.y};
      for (std::size_t q = 0; q < P.size(); ++q) n.visit(P.x[q], P.y[q], P.id[q]);
      p.particle_id = n.id;
      p.slot = std::size_t(std::find(P.id.begin(), P.id.end(), n.id) - P.id.begin());
    }
    out.push_back(p);
  }
  return out;
}

namespace {

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
    const Particles& P = all_particles(s);
    if (p.slot >= P.size() || P.id[p.slot] != p.particle_id)  // moved by a sort, or away
      p.slot = std::size_t(std::find(P.id.begin(), P.id.end(), p.particle_id) - P.id.begin());
    if (p.slot >= P.size()) continue;  // another rank's
    const std::size_t q = p.slot;
    const double row[4] = {P.x[q], P.y[q], P.vx[q], P.vy[q]};
    std::copy(row, row + 4, out);
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
      const Particles& P = all_particles(s);
      if (p.slot >= P.size() || P.id[p.slot] != p.particle_id)  // moved by a sort
        p.slot = std::size_t(std::find(P.id.begin(), P.id.end(), p.particle_id) - P.id.begin());
      const std::size_t q = p.slot;
      const double row[kBodyColumns] = {s.time, P.x[q], P.y[q], P.vx[q], P.vy[q]};
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
