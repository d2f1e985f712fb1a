// rupture/bc/loads.hpp
// Loads besides the edge velocities of bc/velocity_bc.hpp, as the input states them ([loads.NAME],
// docs/loads.md), and what the time step needs to apply them (solver/load_step.hpp). SI units.
// Contract: every load's amplitude is multiplied by its dimensionless time function `factor`;
// forces enter the nodal force as particle external forces f_p scattered with the particle's
// GIMP weights (theory E4); every load's work goes into State::external_work (theory E14).
//   traction:     f_p = factor(t) * traction * length_p on the surface particles of a segment,
//                 length_p the part of the segment their box covers (the shares sum to its
//                 length). traction is global (tx, ty), or normal/shear in the segment frame:
//                 n the outward normal of the material there (normal > 0: tension), s the unit
//                 vector from `from` to `to` (shear > 0 pulls the surface along s).
//   body_force:   f_p = m_p * factor(t) * acceleration on the particles of the chosen bodies.
//   point_force:  a line force F (N/m) at a point inside a body, F factor(t), as the body force
//                 F delta(x - x_s): f_p = factor(t) F w_p on the particles around the point, w_p
//                 the bilinear interpolation weights of x_s among the particle centres (the tent
//                 of half-width the particle spacing 2 l_p in each direction), normalised to sum
//                 to 1, so the particles carry F exactly and its moment about x_s vanishes on a
//                 regular lattice. Then scattered with the GIMP weights like every force.
//   velocity:     the material initially inside a box moves at factor(t) * speed along d;
//                 the perpendicular component stays free (see solver/load_step.hpp).
// Particles are re-sorted during a run: loads hold particle ids (Particles::id), which are stable,
// and the step maps them to indices after every sort.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "bc/time_function.hpp"
#include "particles/particles.hpp"

namespace rupture {

struct TractionLoad {
  std::string name;
  double from[2]{}, to[2]{};  // segment end points, m
  bool global = true;         // traction[] given; else normal/shear in the segment frame
  double traction[2]{};       // Pa (global)
  double normal = 0.0;        // Pa, > 0 tension (segment frame)
  double shear = 0.0;         // Pa, along from -> to
  // Bodies whose surface it loads (their fields); empty = all. Two bodies in different fields
  // meeting along a line (the faces of a crack) each have a surface there: naming one picks it.
  std::vector<int> fields;
  TimeFunction factor;        // dimensionless
};

struct BodyForceLoad {
  std::string name;
  double acceleration[2]{};  // m/s^2
  std::vector<int> fields;   // velocity fields of the bodies it acts on; empty = all
  TimeFunction factor;       // dimensionless
};

struct PointForceLoad {
  std::string name;
  double point[2]{};        // x_s, m
  double force[2]{};        // F, N/m (a line force in plane strain/stress)
  std::vector<int> fields;  // velocity fields of the bodies it may act on; empty = all
  TimeFunction factor;      // dimensionless
};

struct VelocityRegion {
  std::string name;
  double min[2]{}, max[2]{};  // box holding the driven material at t = 0, m
  double direction[2]{1.0, 0.0};  // unit vector d
  double speed = 0.0;         // m/s along d
  std::vector<int> fields;    // velocity fields of the bodies it acts on; empty = all
  TimeFunction factor;        // dimensionless

  double velocity(double t) const { return speed * factor(t); }  // m/s along d
  double displacement(double t) const { return speed * factor.displacement(t); }  // m
};

struct Loads {
  std::vector<TractionLoad> tractions;
  std::vector<BodyForceLoad> body_forces;
  std::vector<VelocityRegion> velocity_regions;
  std::vector<PointForceLoad> point_forces;
  bool empty() const {
    return tractions.empty() && body_forces.empty() && velocity_regions.empty() &&
           point_forces.empty();
  }
};

// The surface particles a traction segment loads, with their share of its length.
struct TractionPatch {
  std::vector<std::uint32_t> ids;  // Particles::id
  std::vector<double> length;      // m, sums to the segment length
  double normal[2]{};              // outward unit normal of the material at the segment
  double tangent[2]{};             // unit vector from -> to
  double segment_length = 0.0;     // m
};

// The traction a load applies on its patch at time t (global frame, Pa): the global vector, or
// normal n + shear s in the segment frame, times factor(t).
inline void patch_traction(const TractionLoad& load, const TractionPatch& patch, double t,
                           double& tx, double& ty) {
  tx = load.traction[0], ty = load.traction[1];
  if (!load.global) {
    tx = load.normal * patch.normal[0] + load.shear * patch.tangent[0];
    ty = load.normal * patch.normal[1] + load.shear * patch.tangent[1];
  }
  const double f = load.factor(t);
  tx *= f, ty *= f;
}

// Finds the surface particles that carry the segment of `load` and their shares: along grid
// lines, the length each GIMP box holds; on an oblique (staircase) edge, where the boxes the line
// cuts hold only about half of it, the length of the segment nearer to each particle centre than
// to any other (sampled, 32 points per particle side). Throws InputError (naming
// loads.NAME.from/to) if no particle (of the load's fields) is adjacent to the segment, if
// material (of those fields) lies on both sides of it, or if the particles carry less than half
// of it.
TractionPatch find_traction_patch(const TractionLoad& load, const Particles& p, double cell_size);

// The particles that carry a point force and their weights (summing to 1).
struct PointSpread {
  std::vector<std::uint32_t> ids;  // Particles::id
  std::vector<double> weight;
};
// The particles of the load's fields within one particle spacing of its point in both
// directions, with their bilinear weights (above). Throws InputError (naming loads.NAME.point)
// when no such particle lies there: the point is outside every body it may act on.
PointSpread find_point_spread(const PointForceLoad& load, const Particles& p);

// Ids of the particles of the region's fields whose centre lies in its box (closed).
std::vector<std::uint32_t> region_particles(const VelocityRegion& r, const Particles& p);

}  // namespace rupture
