// rupture/cohesive/interface_growth.cpp
#include "cohesive/interface_growth.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rupture {
namespace {

// Copies old[i] to grown[i + shift] for every old element.
template <class T>
void carry(const std::vector<T>& old, std::vector<T>& grown, std::size_t shift) {
  for (std::size_t i = 0; i < old.size() && i + shift < grown.size(); ++i) grown[i + shift] = old[i];
}

bool same_point(double ax, double ay, double bx, double by, double tol) {
  return std::hypot(ax - bx, ay - by) <= tol;
}

}  // namespace

std::vector<CrackTip> precrack_tips(const InterfaceSpec& is, double tol, double chord) {
  std::vector<CrackTip> tips;
  const Polyline line = is.geometry();
  if (line.closed || line.num_vertices() < 2) return tips;
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
    // Walk back from the end over `chord` of line (at least the end piece; all of a shorter line).
    const long step = end == 0 ? 1 : -1;
    const std::size_t other = end == 0 ? last : 0;
    double need = std::max(chord, 0.0), bx = x, by = y;
    for (std::size_t i = end; i != other;) {
      const std::size_t j = std::size_t(long(i) + step);
      const double len = std::hypot(line.x[j] - line.x[i], line.y[j] - line.y[i]);
      if (need > 0.0 && len >= need) {
        const double f = need / len;
        bx = line.x[i] + f * (line.x[j] - line.x[i]), by = line.y[i] + f * (line.y[j] - line.y[i]);
        break;
      }
      bx = line.x[j], by = line.y[j], need -= len, i = j;
      if (need <= 0.0) break;
    }
    CrackTip t;
    t.end = end == 0 ? LineEnd::start : LineEnd::end;
    t.frame.x = x, t.frame.y = y;
    const double dx = x - bx, dy = y - by, n = std::hypot(dx, dy);
    t.frame.e1x = dx / n, t.frame.e1y = dy / n;
    tips.push_back(t);
  }
  return tips;
}

void extend_interface(CohesiveInterface& c, LineEnd at, double x, double y, double ux, double uy) {
  if (c.closed) throw std::logic_error("extend_interface: a closed interface has no ends");
  // Distributed (rank_owned set): the grown interface starts without ownership; the caller
  // distributes it again (parallel/halo.hpp, follow_grown_interfaces), every rank having grown
  // it alike from the whole state.
  InterfaceSpec spec = c.spec;
  Polyline line;
  const bool front = at == LineEnd::start;
  if (front) line.x.push_back(x), line.y.push_back(y);
  line.x.insert(line.x.end(), c.x0.begin(), c.x0.end());
  line.y.insert(line.y.end(), c.y0.begin(), c.y0.end());
  if (!front) line.x.push_back(x), line.y.push_back(y);
  spec.line = line;
  spec.segments = int(line.num_vertices() - 1);
  CohesiveInterface g = make_interface(spec);
  const std::size_t node_shift = front ? 1 : 0;
  const std::size_t gp_shift = node_shift * std::size_t(CohesiveInterface::kGauss);
  // Every array of state that a grown line carries (InterfaceArrays' kGrown, per node or Gauss
  // point), over to the new numbering.
  for_each_interface_array([&](const auto& a) {
    if (!a.has(kGrown)) return;
    if (a.extent == InterfaceExtent::segment)
      throw std::logic_error(std::string("extend_interface: no rule to carry the segment array ") + a.name);
    carry(c.*a.member, g.*a.member, a.extent == InterfaceExtent::node ? node_shift : gp_shift);
  });
  const std::size_t k = front ? 0 : g.num_nodes() - 1;  // the new node
  // The new segment's points: separated on a pre-crack (no cohesion), intact with the law on a
  // cohesive crack (drawn open or not): the process zone ahead is modelled by the law.
  const std::size_t first_gp = front ? 0 : g.gp_separated.size() - std::size_t(CohesiveInterface::kGauss);
  for (std::size_t q = first_gp; q < first_gp + std::size_t(CohesiveInterface::kGauss); ++q)
    g.gp_separated[q] = spec.precracked ? 1 : 0;
  g.ux_up[k] = g.ux_lo[k] = ux;
  g.uy_up[k] = g.uy_lo[k] = uy;
  g.node_crack_time[k] = spec.precracked ? c.time : -1.0;
  g.time = c.time;
  g.work = c.work;
  g.light_face_mass = c.light_face_mass;  // from the case at set-up
  c = std::move(g);
}

}  // namespace rupture
