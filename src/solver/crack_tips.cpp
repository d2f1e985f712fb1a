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

std::vector<TipIntegrals> read_tip(const State& L, const InterfaceSpec& is, const TipFrame& tip,
                                   const TipMaterial& material, double time,
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
  std::vector<TipIntegrals> r = tip_integrals(pts, at, domains, material, faces);
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
