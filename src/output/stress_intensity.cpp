// rupture/output/stress_intensity.cpp
#include "output/stress_intensity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/atomic_file.hpp"
#include "fracture/near_tip_field.hpp"
#include "fracture/tip_domain.hpp"
#include "solver/run_state.hpp"

namespace rupture {

namespace {

bool same_point(double ax, double ay, double bx, double by, double tol) {
  return std::hypot(ax - bx, ay - by) <= tol;
}

// The point at arc length s along the interface's nodes and the line's direction there.
TipFrame along_line(const CohesiveInterface& in, double s) {
  const std::vector<double>& s0 = in.s0;
  const std::size_t n = s0.size();
  std::size_t k = std::size_t(std::upper_bound(s0.begin(), s0.end(), s) - s0.begin());
  k = std::clamp<std::size_t>(k == 0 ? 0 : k - 1, 0, n - 2);  // segment k: nodes k, k + 1
  const double len = s0[k + 1] - s0[k], f = len > 0 ? std::clamp((s - s0[k]) / len, 0.0, 1.0) : 0.0;
  TipFrame t;
  t.x = in.x0[k] + f * (in.x0[k + 1] - in.x0[k]);
  t.y = in.y0[k] + f * (in.y0[k + 1] - in.y0[k]);
  t.e1x = in.seg_ny[k], t.e1y = -in.seg_nx[k];  // the tangent (n_y, -n_x): along +s
  return t;
}

}  // namespace

std::vector<TipFrame> crack_tips(const Case& c, const RunState& s, std::size_t k,
                                 const CrackTracker& tracker) {
  const InterfaceSpec& is = c.interfaces[k];
  const CohesiveInterface& in = s.interface(k);
  std::vector<TipFrame> tips;
  if (!is.precracked) {
    const double at = tracker.samples().empty() ? 0.0 : tracker.samples().back().tip;
    tips.push_back(along_line(in, at));
    return tips;
  }
  const Polyline line = is.geometry();
  if (line.closed || line.num_vertices() < 2) return tips;
  const double tol = 1e-6 * c.grid.cell_size;
  const std::vector<Polyline> ties = is.tie_geometries();
  const std::size_t last = line.num_vertices() - 1;
  for (std::size_t end : {std::size_t(0), last}) {
    const double x = line.x[end], y = line.y[end];
    bool meets = false;
    for (const Polyline& t : ties)
      if (t.num_vertices() >= 2)
        meets = meets || same_point(x, y, t.x.front(), t.y.front(), tol) ||
                same_point(x, y, t.x.back(), t.y.back(), tol);
    if (!meets) continue;
    const std::size_t inner = end == 0 ? 1 : last - 1;  // the end piece's other vertex
    TipFrame f;
    f.x = x, f.y = y;
    const double dx = x - line.x[inner], dy = y - line.y[inner], n = std::hypot(dx, dy);
    f.e1x = dx / n, f.e1y = dy / n;
    tips.push_back(f);
  }
  return tips;
}

TipMaterial tip_material(const Case& c, std::size_t k) {
  const ElasticMaterial& m =
      c.materials[std::size_t(c.bodies[std::size_t(c.interfaces[k].upper_body)].material)];
  const double E = m.youngs_modulus, nu = m.poisson_ratio;
  TipMaterial t;
  t.e_prime = c.plane == PlaneMode::strain ? E / (1.0 - nu * nu) : E;
  t.mu = E / (2.0 * (1.0 + nu));
  t.kappa = kolosov_kappa(nu, c.plane);
  return t;
}

void sample_stress_intensity(const Case& c, RunState& s, const std::vector<CrackTracker>& trackers,
                             std::vector<TipSeries>& series) {
  series.resize(c.interfaces.size());
  for (std::size_t k = 0; k < c.interfaces.size(); ++k) {
    const InterfaceSpec& is = c.interfaces[k];
    if (!is.stress_intensity) continue;
    const State& L = s.levels[std::size_t(s.interface_levels[k])];
    std::vector<TiedFields> ties;
    for (const BondedTie& b : L.bonded) ties.push_back({b.upper_field, b.lower_field, &b.nodes});
    const double h = L.grid.cell_size();
    const TipMaterial mat = tip_material(c, k);
    const std::vector<TipFrame> tips = crack_tips(c, s, k, trackers[k]);
    // Tractions on faces (loads on crack faces): their particles' shares, by id.
    struct Carried {
      double length, tx, ty;
    };
    std::unordered_multimap<std::uint32_t, Carried> carried;
    for (std::size_t j = 0; j < L.loads.patches.size(); ++j) {
      double tx, ty;
      patch_traction(L.loads.spec.tractions[j], L.loads.patches[j], s.time, tx, ty);
      if (tx == 0.0 && ty == 0.0) continue;
      const TractionPatch& patch = L.loads.patches[j];
      for (std::size_t i = 0; i < patch.ids.size(); ++i)
        carried.insert({patch.ids[i], {patch.length[i], tx, ty}});
    }
    for (std::size_t t = 0; t < tips.size(); ++t) {
      const double reach = is.j_domains.back() * h;
      const std::vector<DomainPoint> pts =
          tip_domain_points(L.grid, L.fields, L.particles, L.stiffness, ties, tips[t], reach, L.dt);
      std::vector<FaceTraction> faces;
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const auto [lo, hi] = carried.equal_range(pts[i].id);
        for (auto e = lo; e != hi; ++e) faces.push_back({i, e->second.length, e->second.tx, e->second.ty});
      }
      for (double cells : is.j_domains) {
        const JDomain d{0.5 * cells * h, cells * h};
        const TipIntegrals r = tip_integrals(pts, tips[t], d, mat, faces);
        series[k].rows.insert(series[k].rows.end(),
                              {s.time, double(t), tips[t].x, tips[t].y, d.outer, r.J, r.K_I, r.K_II,
                               double(r.points)});
      }
    }
  }
}

void write_stress_intensity(const std::string& dir, const Case& c,
                            const std::vector<TipSeries>& series) {
  for (std::size_t k = 0; k < c.interfaces.size() && k < series.size(); ++k) {
    if (!c.interfaces[k].stress_intensity) continue;
    std::string out = "time,tip,x,y,domain,J,K_I,K_II,points\n";
    const std::vector<double>& r = series[k].rows;
    for (std::size_t i = 0; i + kTipColumns <= r.size(); i += kTipColumns)
      out += fmt::format("{:.9e},{:d},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:d}\n", r[i],
                         int(r[i + 1]), r[i + 2], r[i + 3], r[i + 4], r[i + 5], r[i + 6], r[i + 7],
                         long(r[i + 8]));
    write_file_atomic(dir + "/stress_intensity_" + c.interface_names[k] + ".csv", out);
  }
}

}  // namespace rupture
