// rupture/solver/crack_tips.cpp
#include "solver/crack_tips.hpp"

#include <cmath>
#include <unordered_map>

#include "fracture/near_tip_field.hpp"
#include "fracture/tip_domain.hpp"
#include "solver/rank_exchange.hpp"

namespace rupture {

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

std::vector<InitialStrain> initial_field_strains(const Case& c) {
  std::vector<InitialStrain> out(c.field_names.size());
  for (const BodySpec& b : c.bodies) {
    if (b.stress[0] == 0.0 && b.stress[1] == 0.0 && b.stress[2] == 0.0) continue;
    const ElasticStiffness C = stiffness(c.materials[std::size_t(b.material)], c.plane);
    InitialStrain& e = out[std::size_t(b.field)];
    strain_of(C, b.stress[0], b.stress[1], b.stress[2], e.exx, e.eyy, e.exy);
  }
  return out;
}

namespace {

// The separated Gauss points of the crack's line within `reach` of the tip whose faces touch
// (their traction is contact's, or friction's), as the face loads of the J domains
// (fracture/j_integral.hpp FaceContact). Points that still carry cohesion are left out: their
// traction is the process zone's, and K stays the field outside it, as before. Distributed:
// each rank the segments whose first node it owns (their sums over the ranks are the whole).
std::vector<FaceContact> contacts_near(const CohesiveInterface& c, const TipFrame& tip, double reach) {
  std::vector<FaceContact> out;
  if (c.gp_tn.size() != c.num_segments() * std::size_t(CohesiveInterface::kGauss)) return out;
  for (std::size_t s = 0; s < c.num_segments(); ++s) {
    if (!c.owns(s)) continue;
    const std::size_t e = c.segment_end(s);
    const double len = c.seg_length[s];
    if (!(len > 0.0)) continue;
    const double xa = c.x0[s] + 0.5 * (c.ux_up[s] + c.ux_lo[s]), ya = c.y0[s] + 0.5 * (c.uy_up[s] + c.uy_lo[s]);
    const double xb = c.x0[e] + 0.5 * (c.ux_up[e] + c.ux_lo[e]), yb = c.y0[e] + 0.5 * (c.uy_up[e] + c.uy_lo[e]);
    const double da = std::hypot(xa - tip.x, ya - tip.y), db = std::hypot(xb - tip.x, yb - tip.y);
    if (std::min(da, db) > reach + len) continue;
    const double nx = c.seg_nx[s], ny = c.seg_ny[s];
    const double taux = (c.x0[e] - c.x0[s]) / len, tauy = (c.y0[e] - c.y0[s]) / len;
    const double jxs = (c.jump_x(e) - c.jump_x(s)) / len, jys = (c.jump_y(e) - c.jump_y(s)) / len;
    for (int g = 0; g < CohesiveInterface::kGauss; ++g) {
      const std::size_t i = s * std::size_t(CohesiveInterface::kGauss) + std::size_t(g);
      if (!c.gp_separated[i] || (c.gp_tn[i] == 0.0 && c.gp_tt[i] == 0.0)) continue;
      const double Nb = 0.5 * (1.0 + CohesiveInterface::kGaussXi[g]), Na = 1.0 - Nb;
      // On the upper face: -(T^n n + T^t t), t = (n_y, -n_x) (solver/cohesive_step.cpp).
      const double tn = c.gp_tn[i], tt = c.gp_tt[i];
      out.push_back({Na * xa + Nb * xb, Na * ya + Nb * yb, 0.5 * len * CohesiveInterface::kGaussWeight[g],
                     -(tn * nx + tt * ny), -(tn * ny - tt * nx), -tt * ny, tt * nx, nx, ny, jxs, jys, taux, tauy});
    }
  }
  return out;
}

}  // namespace

std::vector<TipIntegrals> read_tip(const State& L, const CohesiveInterface& line, const InterfaceSpec& is,
                                   const TipFrame& tip, const TipMaterial& material, double time,
                                   const std::vector<InitialStrain>& initial) {
  std::vector<TiedFields> ties;
  for (const BondedTie& b : L.bonded) ties.push_back({b.upper_field, b.lower_field, &b.nodes});
  const double h = L.grid.cell_size();
  // Tractions on faces (loads on crack faces): their particles' shares, by id.
  struct Carried {
    double length, tx, ty;
    const double *from, *to;  // the loaded segment's ends, m
  };
  std::unordered_multimap<std::uint32_t, Carried> carried;
  for (std::size_t j = 0; j < L.loads.patches.size(); ++j) {
    double tx, ty;
    patch_traction(L.loads.spec.tractions[j], L.loads.patches[j], time, tx, ty);
    if (tx == 0.0 && ty == 0.0) continue;
    const TractionPatch& patch = L.loads.patches[j];
    for (std::size_t i = 0; i < patch.ids.size(); ++i)
      carried.insert({patch.ids[i], {patch.length[i], tx, ty, L.loads.spec.tractions[j].from, L.loads.spec.tractions[j].to}});
  }
  const double reach = is.j_domains.back() * h;
  thread_local std::vector<DomainPoint> pts;  // kept: its capacity is reused every step
  // Distributed: the maps summed over the ranks, each rank's own particles' points.
  DomainSums ranks;
  if (L.halo) {
    ranks.sum = [&L](double* v, std::size_t n) { sum_over_ranks(L, v, n); };
    ranks.max = [&L](double* v, std::size_t n) { max_over_ranks(L, v, n); };
  }
  TipFrame at = tip;
  const TipDisplacement u = tip_domain_points(L.grid, L.fields, L.particles, L.stiffness, ties, tip, reach, L.dt,
                                              initial, pts, ranks);
  at.ux = u.ux, at.uy = u.uy;
  std::vector<FaceTraction> faces;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto [lo, hi] = carried.equal_range(pts[i].id);
    for (auto e = lo; e != hi; ++e) {
      const Carried& c = e->second;
      faces.push_back({i, c.length, c.tx, c.ty, c.from[0], c.from[1], c.to[0], c.to[1]});
    }
  }
  std::vector<JDomain> domains;
  for (double cells : is.j_domains) domains.push_back({0.5 * cells * h, cells * h});
  const std::vector<FaceContact> contacts = contacts_near(line, tip, reach);
  std::vector<TipIntegrals> r = tip_integrals(pts, at, domains, material, faces, contacts);
  if (!L.halo) return r;
  // J and M are sums over the points, K linear in M: the ranks' parts add up to the whole
  // domain's (the same bits on every rank, so every rank's growth decision is the same).
  std::vector<double> parts;
  for (const TipIntegrals& t : r) parts.insert(parts.end(), {t.J, t.K_I, t.K_II, double(t.points)});
  sum_over_ranks(L, parts.data(), parts.size());
  for (std::size_t d = 0; d < r.size(); ++d)
    r[d] = {parts[4 * d], parts[4 * d + 1], parts[4 * d + 2], std::size_t(parts[4 * d + 3])};
  return r;
}

}  // namespace rupture
