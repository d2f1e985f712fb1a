// rupture/bc/loads.cpp
#include "bc/loads.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace rupture {

namespace {

// Length of the part of the segment A + u s (0 <= u <= L) inside the box [lo, hi] (clipped
// parametrically, one slab per axis).
double clipped_length(const double A[2], const double s[2], double L, const double lo[2],
                      const double hi[2]) {
  double u0 = 0.0, u1 = L;
  for (int d = 0; d < 2; ++d) {
    if (s[d] == 0.0) {
      if (A[d] < lo[d] || A[d] > hi[d]) return 0.0;
      continue;
    }
    double a = (lo[d] - A[d]) / s[d], b = (hi[d] - A[d]) / s[d];
    if (a > b) std::swap(a, b);
    u0 = std::max(u0, a);
    u1 = std::min(u1, b);
  }
  return std::max(0.0, u1 - u0);
}

// The segment's share of each particle in `patch` when every point of it is carried by the
// nearest particle centre among those (the particles whose box meets it, and their neighbours
// within a box of the segment): midpoint samples, 32 per particle side. Replaces patch.ids/raw.
void nearest_particle_shares(const double A[2], const double s[2], double L, const Particles& p,
                             TractionPatch& patch, std::vector<double>& raw) {
  // Candidates: the load's particles (those already found) set the fields and the reach.
  std::vector<std::uint32_t> found = patch.ids;
  std::sort(found.begin(), found.end());
  double reach = 0.0, side = INFINITY;
  std::vector<std::uint8_t> fields;
  for (std::size_t k = 0; k < p.size(); ++k)
    if (std::binary_search(found.begin(), found.end(), p.id[k])) {
      reach = std::max(reach, 2.0 * std::hypot(p.half_x[k], p.half_y[k]));
      side = std::min(side, 2.0 * std::min(p.half_x[k], p.half_y[k]));
      if (std::find(fields.begin(), fields.end(), p.field[k]) == fields.end())
        fields.push_back(p.field[k]);
    }
  struct Candidate {
    double t, x, y;
    std::uint32_t id;
  };
  std::vector<Candidate> c;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (std::find(fields.begin(), fields.end(), p.field[k]) == fields.end()) continue;
    const double rx = p.x[k] - A[0], ry = p.y[k] - A[1];
    const double t = rx * s[0] + ry * s[1], n = rx * s[1] - ry * s[0];
    if (t > -reach && t < L + reach && std::fabs(n) < reach) c.push_back({t, p.x[k], p.y[k], p.id[k]});
  }
  std::sort(c.begin(), c.end(), [](const Candidate& a, const Candidate& b) { return a.t < b.t; });
  const long samples = std::max(1L, long(std::ceil(32.0 * L / side)));
  const double du = L / double(samples);
  std::vector<double> share(c.size(), 0.0);
  std::size_t first = 0;
  for (long q = 0; q < samples; ++q) {
    const double u = (double(q) + 0.5) * du, qx = A[0] + u * s[0], qy = A[1] + u * s[1];
    while (first < c.size() && c[first].t < u - reach) ++first;
    double best = reach * reach;
    std::size_t arg = c.size();
    for (std::size_t k = first; k < c.size() && c[k].t <= u + reach; ++k) {
      const double d2 = (c[k].x - qx) * (c[k].x - qx) + (c[k].y - qy) * (c[k].y - qy);
      if (d2 < best) best = d2, arg = k;
    }
    if (arg < c.size()) share[arg] += du;
  }
  patch.ids.clear();
  raw.clear();
  for (std::size_t k = 0; k < c.size(); ++k)
    if (share[k] > 0.0) patch.ids.push_back(c[k].id), raw.push_back(share[k]);
}

}  // namespace

TractionPatch find_traction_patch(const TractionLoad& load, const Particles& p, double cell_size) {
  TractionPatch patch;
  const double* A = load.from;
  const double dx = load.to[0] - A[0], dy = load.to[1] - A[1];
  const double L = std::hypot(dx, dy);
  const double s[2] = {dx / L, dy / L};
  const double right[2] = {s[1], -s[0]};  // unit normal to the right of from -> to
  patch.segment_length = L;
  patch.tangent[0] = s[0], patch.tangent[1] = s[1];
  const double tol = 1e-9 * cell_size;
  const std::string key = "loads." + load.name;
  const std::string seg = fmt::format("[{:g}, {:g}] -> [{:g}, {:g}]", A[0], A[1], load.to[0], load.to[1]);
  std::vector<double> raw;
  int left_side = 0, right_side = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (!load.fields.empty() &&
        std::find(load.fields.begin(), load.fields.end(), int(p.field[k])) == load.fields.end())
      continue;
    const double lo[2] = {p.x[k] - p.half_x[k] - tol, p.y[k] - p.half_y[k] - tol};
    const double hi[2] = {p.x[k] + p.half_x[k] + tol, p.y[k] + p.half_y[k] + tol};
    const double len = clipped_length(A, s, L, lo, hi);
    if (len <= 4.0 * tol) continue;  // a corner or an edge end touching: no share
    const double side = (p.x[k] - A[0]) * right[0] + (p.y[k] - A[1]) * right[1];
    if (side > tol) ++right_side;
    if (side < -tol) ++left_side;
    patch.ids.push_back(p.id[k]);
    raw.push_back(len);
  }
  if (patch.ids.empty())
    throw InputError(fmt::format(
        "input keys '{0}.from', '{0}.to' = {1}: no particle is adjacent to the segment; a "
        "traction segment must lie on the surface of the material",
        key, seg));
  if (left_side > 0 && right_side > 0)
    throw InputError(fmt::format(
        "input keys '{0}.from', '{0}.to' = {1}: material lies on both sides of the segment ({2} "
        "and {3} particles); a traction segment must lie on the surface of the material (on a "
        "line between two bodies, e.g. a crack's faces, name the loaded one: {0}.bodies = [...])",
        key, seg, left_side, right_side));
  // Outward normal: away from the material.
  const double sign = right_side > 0 ? -1.0 : 1.0;
  patch.normal[0] = sign * right[0], patch.normal[1] = sign * right[1];
  double covered = 0.0;
  for (double len : raw) covered += len;
  // On a surface made of whole particle boxes (along grid lines) the boxes cover the segment
  // exactly: each particle carries the length its box holds. On an oblique staircase only the
  // boxes the line cuts meet it, about half of the segment, so half the surface particles would
  // carry all the load; there every point of the segment goes to the nearest surface particle.
  if (std::fabs(covered - L) > 1e-6 * L) nearest_particle_shares(A, s, L, p, patch, raw);
  // Shares sum to the segment length.
  double total = 0.0;
  for (double len : raw) total += len;
  if (total < 0.5 * L || total > 1.5 * L)
    throw InputError(fmt::format(
        "input keys '{0}.from', '{0}.to' = {1}: the particles along the segment carry {2:g} m "
        "of its {3:g} m; a traction segment must lie on the surface of the material",
        key, seg, total, L));
  patch.length.resize(raw.size());
  for (std::size_t k = 0; k < raw.size(); ++k) patch.length[k] = raw[k] * (L / total);
  return patch;
}

PointSpread find_point_spread(const PointForceLoad& load, const Particles& p) {
  // (id, weight) of every particle within one spacing of the point, in id order (one process
  // and a distributed rank's share list them alike).
  std::vector<std::pair<std::uint32_t, double>> found;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (!load.fields.empty() &&
        std::count(load.fields.begin(), load.fields.end(), int(p.field[k])) == 0)
      continue;
    const double sx = 2.0 * p.half_x[k], sy = 2.0 * p.half_y[k];  // the particle spacing
    const double wx = 1.0 - std::fabs(p.x[k] - load.point[0]) / sx;
    const double wy = 1.0 - std::fabs(p.y[k] - load.point[1]) / sy;
    if (wx > 0.0 && wy > 0.0) found.emplace_back(p.id[k], wx * wy);
  }
  std::sort(found.begin(), found.end());
  double total = 0.0;
  for (const auto& e : found) total += e.second;
  if (!(total > 0.0))
    throw InputError(fmt::format(
        "input key 'loads.{}.point' = [{:g}, {:g}]: no particle{} lies within one particle "
        "spacing of the point; a point force must act inside a body's material",
        load.name, load.point[0], load.point[1], load.fields.empty() ? "" : " of the bodies it names"));
  PointSpread s;
  for (const auto& [id, w] : found) s.ids.push_back(id), s.weight.push_back(w / total);
  return s;
}

std::vector<std::uint32_t> region_particles(const VelocityRegion& r, const Particles& p) {
  std::vector<std::uint32_t> ids;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const bool in_field = r.fields.empty() ||
                          std::count(r.fields.begin(), r.fields.end(), int(p.field[k])) > 0;
    if (in_field && p.x[k] >= r.min[0] && p.x[k] <= r.max[0] && p.y[k] >= r.min[1] &&
        p.y[k] <= r.max[1])
      ids.push_back(p.id[k]);
  }
  return ids;
}

}  // namespace rupture
