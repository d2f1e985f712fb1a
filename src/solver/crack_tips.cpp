// rupture/solver/crack_tips.cpp
#include "solver/crack_tips.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

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
// Into `out` (cleared first).
void contacts_near(const CohesiveInterface& c, const TipFrame& tip, double reach, std::vector<FaceContact>& out) {
  out.clear();
  if (c.gp_tn.size() != c.num_segments() * std::size_t(CohesiveInterface::kGauss)) return;
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
}

}  // namespace

std::vector<TipIntegrals> read_tip(const State& L, const CohesiveInterface& line, const InterfaceSpec& is,
                                   const TipFrame& tip, const TipMaterial& material, double time,
                                   const std::vector<InitialStrain>& initial) {
  // Scratch kept by the calling thread from read to read (a read every step: no allocation once
  // their capacities are reached), named by references.
  thread_local std::vector<TiedFields> kept_ties;
  thread_local std::vector<DomainPoint> kept_points;
  thread_local std::vector<std::pair<std::uint32_t, std::uint32_t>> kept_ids;
  thread_local std::vector<FaceTraction> kept_faces;
  thread_local std::vector<JDomain> kept_domains;
  std::vector<TiedFields>& ties = kept_ties;
  std::vector<DomainPoint>& pts = kept_points;
  ties.clear();
  for (const BondedTie& b : L.bonded) ties.push_back({b.upper_field, b.lower_field, &b.nodes});
  const double h = L.grid.cell_size();
  const double reach = is.j_domains.back() * h;
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
  // Tractions on faces (loads on crack faces): the shares of the domain's particles that a loaded
  // patch holds, found by id (the points' ids sorted once; a patch's particles looked up in
  // them), in the points' order and, for one point, in the patches' order.
  std::vector<FaceTraction>& faces = kept_faces;
  faces.clear();
  if (!L.loads.patches.empty() && !pts.empty()) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>>& ids = kept_ids;
    ids.clear();
    for (std::size_t i = 0; i < pts.size(); ++i) ids.push_back({pts[i].id, std::uint32_t(i)});
    std::sort(ids.begin(), ids.end());
    for (std::size_t j = 0; j < L.loads.patches.size(); ++j) {
      double tx, ty;
      patch_traction(L.loads.spec.tractions[j], L.loads.patches[j], time, tx, ty);
      if (tx == 0.0 && ty == 0.0) continue;
      const TractionPatch& patch = L.loads.patches[j];
      const double *from = L.loads.spec.tractions[j].from, *to = L.loads.spec.tractions[j].to;
      for (std::size_t q = 0; q < patch.ids.size(); ++q) {
        const auto hit = std::lower_bound(ids.begin(), ids.end(), std::make_pair(patch.ids[q], std::uint32_t(0)));
        for (auto e = hit; e != ids.end() && e->first == patch.ids[q]; ++e)
          faces.push_back({e->second, patch.length[q], tx, ty, from[0], from[1], to[0], to[1]});
      }
    }
    std::stable_sort(faces.begin(), faces.end(),
                     [](const FaceTraction& a, const FaceTraction& b) { return a.point < b.point; });
  }
  std::vector<JDomain>& domains = kept_domains;
  domains.clear();
  for (double cells : is.j_domains) domains.push_back({0.5 * cells * h, cells * h});
  thread_local std::vector<FaceContact> kept_contacts;
  std::vector<FaceContact>& contacts = kept_contacts;
  contacts_near(line, tip, reach, contacts);
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
