// rupture/cohesive/interface.cpp
#include "cohesive/interface.hpp"

#include <cmath>
#include <utility>

namespace rupture {

Polyline InterfaceSpec::geometry() const {
  if (line.num_vertices() >= 2) return line;
  Polyline p;
  p.x = {start, end};
  p.y = {y, y};
  return p;
}

std::vector<Polyline> InterfaceSpec::tie_geometries() const {
  if (!bonded_lines.empty() || !bonded) return bonded_lines;
  Polyline p;
  p.x = {bonded_from, bonded_to};
  p.y = {y, y};
  return {p};
}

namespace {
// The last stretch containing arc length s wins (0: none, the interface's own law).
std::uint16_t stretch_at(const InterfaceSpec& spec, double s) {
  std::uint16_t w = 0;
  for (std::size_t k = 0; k < spec.stretches.size(); ++k)
    if (s >= spec.stretches[k].from && s <= spec.stretches[k].to) w = std::uint16_t(k + 1);
  return w;
}
}  // namespace

void for_each_gauss_point_law(const InterfaceSpec& spec, const std::function<bool(std::uint16_t)>& visit) {
  const Polyline line = spec.geometry();
  const LineNodes nodes = discretize(line, spec.segments);
  const std::size_t n = nodes.x.size(), nseg = line.closed ? n : n - 1;
  const double* xi = CohesiveInterface::kGaussXi;
  for (std::size_t s = 0; s < nseg; ++s) {
    const std::size_t b = line.closed && s + 1 == n ? 0 : s + 1;  // as segment_end
    const double len = std::hypot(nodes.x[b] - nodes.x[s], nodes.y[b] - nodes.y[s]);
    for (int q = 0; q < CohesiveInterface::kGauss; ++q)
      if (!visit(spec.stretches.empty() ? 0 : stretch_at(spec, nodes.s[s] + 0.5 * (1.0 + xi[q]) * len))) return;
  }
}

namespace {
// A rate-and-state law whose parameters vary continuously along the line (its taper, the
// spec's profile) is resolved once here at every Gauss point and node: the stretch's law there,
// RateStateFriction::at (the taper) and RateStateProfile::apply. A Gauss point's position is
// computed exactly as the interface loop computes the one it gives the law (h.x, h.y:
// solver/cohesive_step.cpp), so the taper gives the same law, bit for bit, as evaluated there.
void resolve_point_laws(CohesiveInterface& c) {
  const auto* base = std::get_if<RateStateFriction>(&c.spec.law);
  if (!base) return;
  bool varies = base->taper.on || c.spec.profile.on();
  for (const LawStretch& st : c.spec.stretches) varies = varies || std::get<RateStateFriction>(st.law).taper.on;
  if (!varies) return;
  const RateStateProfile& prof = c.spec.profile;
  const std::size_t nseg = c.num_segments(), G = std::size_t(CohesiveInterface::kGauss);
  const double* xi = CohesiveInterface::kGaussXi;
  c.gp_point_law.resize(nseg * G);
  for (std::size_t s = 0; s < nseg; ++s) {
    const std::size_t e = c.segment_end(s);
    for (std::size_t q = 0; q < G; ++q) {
      const std::size_t i = s * G + q;
      const double Na = 0.5 * (1.0 - xi[q]), Nb = 0.5 * (1.0 + xi[q]);
      const double x = Na * c.x0[s] + Nb * c.x0[e], y = Na * c.y0[s] + Nb * c.y0[e];
      const double arc = c.s0[s] + 0.5 * (1.0 + xi[q]) * c.seg_length[s];
      const RateStateFriction& L = c.gp_law.empty() ? *base : law_of(c, *base, c.gp_law[i]);
      c.gp_point_law[i] = prof.apply(L.at(x, y), x, y, arc);
    }
  }
  c.node_point_law.resize(c.num_nodes());
  for (std::size_t k = 0; k < c.num_nodes(); ++k) {
    const RateStateFriction& L = c.node_law.empty() ? *base : law_of(c, *base, c.node_law[k]);
    c.node_point_law[k] = prof.apply(L.at(c.x0[k], c.y0[k]), c.x0[k], c.y0[k], c.s0[k]);
  }
}
}  // namespace

CohesiveInterface make_interface(const InterfaceSpec& spec) {
  CohesiveInterface c;
  c.spec = spec;
  const Polyline line = spec.geometry();
  c.closed = line.closed;
  LineNodes nodes = discretize(line, spec.segments);
  c.x0 = std::move(nodes.x);
  c.y0 = std::move(nodes.y);
  c.s0 = std::move(nodes.s);
  const std::size_t n = c.x0.size(), nseg = c.num_segments();
  c.seg_nx.resize(nseg);
  c.seg_ny.resize(nseg);
  c.seg_length.resize(nseg);
  for (std::size_t s = 0; s < nseg; ++s) {
    const std::size_t b = c.segment_end(s);
    const double dx = c.x0[b] - c.x0[s], dy = c.y0[b] - c.y0[s];
    const double len = std::hypot(dx, dy);  // exactly |dx| on a horizontal line
    c.seg_length[s] = len;
    c.seg_nx[s] = -dy / len;
    c.seg_ny[s] = dx / len;
  }
  c.node_nx.resize(n);
  c.node_ny.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    double nx = 0.0, ny = 0.0;
    if (k < nseg) nx += c.seg_nx[k], ny += c.seg_ny[k];
    const bool has_prev = k > 0 || c.closed;
    const std::size_t prev = k > 0 ? k - 1 : nseg - 1;
    if (has_prev) nx += c.seg_nx[prev], ny += c.seg_ny[prev];
    const double len = std::hypot(nx, ny);
    c.node_nx[k] = nx / len, c.node_ny[k] = ny / len;
  }
  for (auto* v : {&c.ux_up, &c.uy_up, &c.ux_lo, &c.uy_lo, &c.fx_node, &c.fy_node, &c.stiffness_node,
                  &c.jump_before, &c.last_increment_n, &c.last_increment_t, &c.streak_base})
    v->assign(n, 0.0);
  c.node_crack_time.assign(n, -1.0);
  c.reversal_streak.assign(n, 0);
  const std::size_t g = nseg * CohesiveInterface::kGauss;
  for (auto* v : {&c.gp_dn, &c.gp_dt, &c.gp_tn, &c.gp_tt}) v->assign(g, 0.0);
  c.gp_separated.assign(g, spec.precracked || spec.drawn_open ? 1 : 0);
  c.gp_damage.assign(g, 0.0);
  c.gp_slip.assign(g, 0.0);
  c.gp_state.assign(g, 0.0);
  c.gp_rate.assign(g, 0.0);
  c.gp_normal.assign(g, 0.0);
  if (spec.precracked || spec.drawn_open) c.node_crack_time.assign(n, 0.0);
  c.node_rupture_time.assign(n, -1.0);
  c.node_peak_slip_rate.assign(n, 0.0);
  c.node_slip_path.assign(n, 0.0);
  c.node_slip_rate.assign(n, 0.0);
  if (!spec.stretches.empty()) {
    auto which = [&](double s) { return stretch_at(spec, s); };
    const double* xi = CohesiveInterface::kGaussXi;
    c.gp_law.resize(g);
    for (std::size_t s = 0; s < nseg; ++s)
      for (int q = 0; q < CohesiveInterface::kGauss; ++q)
        c.gp_law[s * CohesiveInterface::kGauss + std::size_t(q)] =
            which(c.s0[s] + 0.5 * (1.0 + xi[q]) * c.seg_length[s]);
    c.node_law.resize(n);
    for (std::size_t k = 0; k < n; ++k) c.node_law[k] = which(c.s0[k]);
  }
  for (auto* v : {&c.seg_fa_x, &c.seg_fa_y, &c.seg_fb_x, &c.seg_fb_y, &c.seg_ka, &c.seg_kb})
    v->assign(nseg, 0.0);
  resolve_point_laws(c);
  for (const auto& [faces, out] : {std::pair{&spec.upper_faces, &c.node_faces_up},
                                   std::pair{&spec.lower_faces, &c.node_faces_lo}}) {
    if (faces->empty()) continue;
    out->resize(n);
    for (std::size_t k = 0; k < n; ++k) (*out)[k] = face_fields_at(c, *faces, k);
  }
  return c;
}

FaceFields face_fields_at(const CohesiveInterface& c, const std::vector<FaceField>& faces, std::size_t k) {
  const std::size_t nseg = c.num_segments();
  const bool has_prev = k > 0 || c.closed, has_next = k < nseg;
  const double lo = c.s0[k] - (has_prev ? 0.5 * c.seg_length[k > 0 ? k - 1 : nseg - 1] : 0.0);
  const double hi = c.s0[k] + (has_next ? 0.5 * c.seg_length[k] : 0.0);
  // A closed line's arc length wraps: node 0's part begins before the line's end.
  const double length = c.closed ? c.length() : 0.0;
  // The field at arc length s (the one whose stretch holds it; the last one's runs on through
  // the end of a closed line to the first change).
  auto field_at = [&](double s) {
    if (c.closed && s < 0.0) s += length;
    int f = c.closed ? faces.back().field : faces.front().field;
    for (const FaceField& e : faces)
      if (e.from <= s) f = e.field;
    return std::uint8_t(f);
  };
  for (std::size_t q = 0; q < faces.size(); ++q)
    for (const double shift : {0.0, -length, length}) {
      const double at = faces[q].from + shift;
      if ((q > 0 || c.closed) && at > lo && at < hi)
        return {field_at(lo), std::uint8_t(faces[q].field), (at - lo) / (hi - lo)};
      if (!c.closed) break;
    }
  return {field_at(0.5 * (lo + hi)), 0, 1.0};
}

double node_state(const CohesiveInterface& c, std::size_t k) {
  const auto* base = std::get_if<RateStateFriction>(&c.spec.law);
  if (!base) return 0.0;
  const std::size_t G = std::size_t(CohesiveInterface::kGauss);
  const auto psi = [&](std::size_t i) { return gauss_point_law(c, *base, i).psi_init + c.gp_state[i]; };
  const bool has_next = k < c.num_segments(), has_prev = k > 0 || c.closed;
  const std::size_t prev = k > 0 ? k - 1 : c.num_segments() - 1;
  const double sum = (has_next ? psi(k * G) : 0.0) + (has_prev ? psi(prev * G + G - 1) : 0.0);
  const int count = int(has_next) + int(has_prev);
  return count > 0 ? sum / count : 0.0;
}

double CohesiveInterface::stored_energy() const {
  const double* w = kGaussWeight;
  return std::visit(
      [&](const auto& law) {
        double e = 0.0;
        for (std::size_t s = 0; s < num_segments(); ++s) {
          if (!owns(s)) continue;
          const double half = 0.5 * seg_length[s];
          for (int g = 0; g < kGauss; ++g) {
            const std::size_t i = s * kGauss + std::size_t(g);
            const GaussHistory h{gp_damage[i], gp_slip[i], gp_dt[i], gp_state[i], gp_rate[i], gp_normal[i]};
            const auto& L = gauss_point_law(*this, law, i);
            if (!gp_separated[i])
              e += w[g] * half * L.stored_energy(gp_dn[i], gp_dt[i], h);
            else if (spec.contact)
              e += w[g] * half * spec.contact_law.stored_energy(gp_dn[i], gp_dt[i], h);
          }
        }
        return e;
      },
      spec.law);
}

}  // namespace rupture
