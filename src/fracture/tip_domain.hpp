// rupture/fracture/tip_domain.hpp
// The material points of a crack tip's J-integral domain, from a level's particles and grid
// (fracture/j_integral.hpp's DomainPoint): stress and strain from the particle (its material's
// compliance), its displacement u = x - X (plus the initial strain's, below), the displacement and velocity gradients from the particles' displacement
// u = x - X and velocity mapped to the grid nodes of their own field (mass-weighted GIMP
// weights, theory E3) and differentiated with the particle's GIMP gradients, as the time step
// differentiates the velocity; the acceleration from the last step's nodal velocity increment
// (GridFields::dvel / dt). The two fields of a crack meet at tied nodes (bonded stretches: the
// intact material beyond a tip) as one body there, so the maps sum both fields at those nodes.
// Contract: every point within `reach` + a cell of the tip (m) is returned; the nodal maps see every particle that reaches their
// nodes. One level (the caller passes the level holding the tip). Distributed runs pass
// DomainSums: each rank maps its own particles, the maps are summed over the ranks before they
// are differentiated, and each rank returns its own particles' points (their integrals are sums:
// the caller sums them over the ranks too).
#pragma once
#include <cstddef>
#include <functional>
#include <vector>

#include "fracture/j_integral.hpp"
#include "grid/grid.hpp"
#include "material/elastic.hpp"
#include "particles/particles.hpp"

namespace rupture {

// Grid nodes where two fields are one body (solver/state.hpp BondedTie, as plain data).
struct TiedFields {
  int upper_field = 0, lower_field = 0;
  const std::vector<std::size_t>* nodes = nullptr;  // grid nodes, increasing
};

// The uniform strain a field's material was given at t = 0 (a body's initial stress through its
// compliance; tensor components): u = x - X does not hold it, so it is added to the
// displacement gradient, and the domain sees the displacement from the stress-free state that
// its stress and strain belong to.
struct InitialStrain {
  double exx = 0.0, eyy = 0.0, exy = 0.0;
};

// What the ranks of a distributed run add up (empty functions: one process). `sum`: element-wise
// sums over the ranks, the same bits on every rank; `max`: element-wise largest values. A read
// calls each once (every call is a collective, and a read every step is many of them).
struct DomainSums {
  std::function<void(double*, std::size_t)> sum;
  std::function<void(double*, std::size_t)> max;
  bool distributed() const { return bool(sum); }
};

// dt: the last step's (s; 0 gives zero accelerations). initial: per field (empty: none).
std::vector<DomainPoint> tip_domain_points(const Grid& g, const GridFields& fields,
                                           const Particles& P,
                                           const std::vector<ElasticStiffness>& stiffness,
                                           const std::vector<TiedFields>& ties,
                                           const TipFrame& tip, double reach, double dt,
                                           const std::vector<InitialStrain>& initial = {});
// The same into `out` (cleared first; a caller that keeps it keeps its capacity: the points
// of a domain are some hundred kilobytes, which a fresh allocation every step page-faults in).
// Returns the displacement at the tip (m; TipFrame::ux, uy): the mass-weighted mean of every
// field's map there (bilinear weights of the cell holding it), the same on every rank.
struct TipDisplacement {
  double ux = 0.0, uy = 0.0;
};
TipDisplacement tip_domain_points(const Grid& g, const GridFields& fields, const Particles& P,
                       const std::vector<ElasticStiffness>& stiffness,
                       const std::vector<TiedFields>& ties, const TipFrame& tip, double reach,
                       double dt, const std::vector<InitialStrain>& initial,
                       std::vector<DomainPoint>& out, const DomainSums& ranks = {});

}  // namespace rupture
