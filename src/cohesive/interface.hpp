// rupture/cohesive/interface.hpp
// A cohesive interface between two velocity fields along a polyline (theory §3, E7-E9).
// Cohesive nodes lie on the line (cohesive/polyline.hpp: a node on every vertex); each exists
// twice, an upper face (moving with the field of the body the line's normal points into) and
// a lower face (the other body's field), coincident at t = 0. Each segment has its own frame:
// normal n (the line direction turned +90 degrees) and tangent t = (n_y, -n_x); jumps
// (upper minus lower face displacement) and tractions are computed in that frame, so a
// horizontal line drawn in +x has n = +y, t = +x as in docs/theory.md §3.
// Face velocities are the grid velocities of their field interpolated with the bilinear hat at
// the face position; forces go back to the same grid nodes with the same weights.
// Separation (theory §3): a Gauss point whose jump magnitude reaches separation_factor * delta_t
// carries no traction from then on; a node whose jump reaches it counts as cracked (E10).
// Where the two bodies are bonded instead (bonded_lines), their fields share every grid node
// near the line (solver/cohesive_step.hpp: tie_bonded_nodes): one continuum there.
// Units: m, m/s, N per unit thickness (N/m), J/m.
#pragma once
#include <functional>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <variant>
#include <vector>

#include "cohesive/fault_profile.hpp"
#include "cohesive/law.hpp"
#include "cohesive/polyline.hpp"
#include "fracture/growth_criterion.hpp"
#include "geometry/shape.hpp"

namespace rupture {

// A stretch of an interface with its own law parameters (a barrier, a nucleation patch, a
// prestress patch): the Gauss points whose arc length from the line's start lies in
// [from, to] use `law` (same law type as the interface's). Later stretches override earlier.
struct LawStretch {
  double from = 0.0, to = 0.0;  // m, arc length along the line
  CohesiveLaw law;
};

// Where a face's field changes along the line: from arc length `from` (m, along the line from
// its start) on, the face lies on `field` (the body part `body`). Another line inside a body
// that ends on this one (a T-junction) splits the part holding this face in two, one on each
// side of the end (input/parse_body_split.cpp).
struct FaceField {
  double from = 0.0;  // m
  int field = 0, body = 0;
};

struct InterfaceSpec {
  int upper_field = 0, lower_field = 1;  // the velocity fields of the two faces
  int upper_body = 0, lower_body = 1;    // the bodies named (Case::bodies); the normal points
                                         // into the upper one
  // Faces whose field changes along the line (T-junctions), in increasing `from`, the first
  // from 0; empty: the whole face on upper_field / lower_field. The tied stretches (bonded_lines)
  // stay on upper_field / lower_field.
  std::vector<FaceField> upper_faces, lower_faces;
  // Where the interface lies. Empty: the horizontal form, the line (start, y) -> (end, y).
  Polyline line;
  double y = 0.0;                 // m
  double start = 0.0, end = 0.0;  // m
  int segments = 1;
  // The traction-separation law (cohesive/law.hpp), chosen once per interface.
  CohesiveLaw law = XuNeedleman{};
  std::vector<LawStretch> stretches;  // stretches with their own parameters (none: one law)
  // law = "rate_state": its parameters tabulated along the line (off: none tabulated).
  RateStateProfile profile;
  // A node has ruptured once its slip rate |dDt/dt| first exceeds this (m/s; the SCEC
  // benchmarks' rupture-time definition, 1 mm/s).
  double rupture_slip_rate = 1e-3;
  double separation_factor = 5.0;  // Xu-Needleman: separated at |jump| = this x delta_t (theory §3: 5)
  // No cohesion at all (a pre-crack): every point starts separated; with `contact`, its faces
  // still press and rub on each other.
  bool precracked = false;
  // A cohesive law drawn open (a cut or notch whose grown segments carry the law; input key
  // drawn_open): the drawn line's points start separated as a pre-crack's, the segments a
  // growing crack adds start intact with the law (cohesive/interface_growth.hpp).
  bool drawn_open = false;
  // Contact of separated points (after separation, and on a pre-crack): faces in compression
  // do not pass through each other; optional Coulomb friction (cohesive/contact.hpp). Without
  // it a separated point carries no traction (theory §3, the paper's choice).
  bool contact = false;
  ContactLaw contact_law;
  // Where the two fields are bonded (tied): any number of lines (bonded_points gives one; a
  // line inside one body that ends inside it gets one beyond each such end, input/). None and
  // `bonded`: the horizontal form, along y from bonded_from to bonded_to.
  std::vector<Polyline> bonded_lines;
  bool bonded = false;
  double bonded_from = 0.0, bonded_to = 0.0;  // m

  // K_I, K_II and J at the crack's tips over time (fracture/j_integral.hpp; docs/fracture.md):
  // on the circular domains of outer radii j_domains (in cells; inner: half of each).
  bool stress_intensity = false;
  std::vector<double> j_domains{4.0, 6.0, 8.0};
  // A pre-crack's tips grow by this criterion (solver/crack_growth.hpp; off: they stay).
  GrowthLaw growth;
  // Read a growing tip as running at its speed (fracture/running_tip_field.hpp: the running
  // tip's auxiliary fields, K of a running tip; the energy criterion's G with Freund's A_I, A_II);
  // off: every tip read with the stationary forms.
  bool running_tip = false;
  // Nucleation at the drawn line (input key nucleation = "strength"; solver/crack_nucleation.hpp):
  // > 0, the line is intact material (tied like its extension) until the mean normal stress
  // across one of its segments, over the particles within a cell of it, reaches this (Pa); then
  // it is the crack drawn (its law's segments, or a cut with drawn_open) and grows. 0: none.
  double nucleation_strength = 0.0;
  // The velocity fields kept for the wedges of growth.max_branches branch events, in order
  // (input/: named NAME.branchK; no particles until a tip splits, solver/crack_branching.hpp).
  std::vector<int> branch_fields;
  // A growing crack drawn inside a body: the parts of the body that other lines in it have cut
  // off for good since the run began (derived at run time before each growth step, not read:
  // solver/crack_junction.hpp cut_off_parts), each the points on its side of every cut in its
  // list (Region::minus_parts); its material is beyond the crack's reach (solver/crack_cut.hpp).
  std::vector<std::vector<Side>> reach_cut_off;

  Polyline geometry() const;                     // line, or its horizontal form
  std::vector<Polyline> tie_geometries() const;  // bonded_lines, or the horizontal form (none
                                                 // if not bonded)
};

// A face point's grid stencil (solver/cohesive_step.cpp): it moves with, and loads, its own
// field's four nodes around it with weights c (bilinear weight x nodal mass, normalized; all
// zero where its field has no mass). Computed once per step, after the bonded tie, and used by
// both the force spread and the face motion, so the two are transposes of each other. A face
// node on a T-junction (FaceFields with share < 1) uses two fields' four nodes each, the two
// normalized parts weighted by the share; otherwise slots 4-7 have c = 0.
struct FaceStencil {
  static constexpr int kSlots = 8;
  std::size_t node[kSlots];  // grid index, field offset included
  double c[kSlots];
  double mass = 0.0;  // the face's mass, sum of bilinear weight x nodal mass, kg/m
};

// The fields a face node moves with where its face changes field along the line (a T-junction:
// InterfaceSpec::upper_faces): `share` of it with field a's material and the rest with field
// b's, the shares of its part of the line (half of each segment beside it) on either side of the
// change. share = 1 (b unused) for a node wholly on one part.
struct FaceFields {
  std::uint8_t a = 0, b = 0;
  double share = 1.0;
};

// Every array of state is also listed in InterfaceArrays below (restart is bitwise: the
// checkpoint walks that list), except `spec`, which is rebuilt from the case, and the derived
// and scratch arrays marked so.
struct CohesiveInterface {
  static constexpr int kGauss = 4;  // Gauss points per segment (E9)
  // The 4-point Gauss-Legendre rule on [-1, 1]: abscissae and weights (they sum to 2).
  static constexpr double kGaussXi[kGauss] = {-0.8611363115940526, -0.3399810435848563,
                                              0.3399810435848563, 0.8611363115940526};
  static constexpr double kGaussWeight[kGauss] = {0.3478548451374538, 0.6521451548625461,
                                                  0.6521451548625461, 0.3478548451374538};
  InterfaceSpec spec;
  bool closed = false;                     // the last segment ends on node 0
  std::vector<double> x0, y0;              // reference node positions, m (N + 1; N if closed)
  std::vector<double> s0;                  // arc length of each node from the line's start, m
  std::vector<double> node_nx, node_ny;    // unit normal at a node (mean of its segments')
  std::vector<double> seg_nx, seg_ny;      // unit normal of each segment (tangent: (n_y, -n_x))
  std::vector<double> seg_length;          // m
  std::vector<double> ux_up, uy_up;        // upper-face displacement, m
  std::vector<double> ux_lo, uy_lo;        // lower-face displacement, m
  std::vector<double> fx_node, fy_node;    // cohesive force on the upper face node, N/m
  std::vector<double> node_crack_time;     // time the node's jump reached the criterion (or -1),
                                           // interpolated inside the step where it crossed, s
  std::vector<double> gp_dn, gp_dt;        // jump at each Gauss point (segment-major), m
  std::vector<double> gp_tn, gp_tt;        // traction at each Gauss point, Pa
  std::vector<std::uint8_t> gp_separated;  // irreversible separation flags
  std::vector<double> gp_damage, gp_slip;  // law history per Gauss point (GaussHistory)
  std::vector<double> gp_state, gp_rate;   // rate-and-state history (GaussHistory; else 0)
  std::vector<double> gp_normal;           // sigma* - sigma0, Pa (GaussHistory::normal_seen)
  // Which law each Gauss point and node uses: 0 = spec.law, k = spec.stretches[k - 1].law
  // (derived from the spec, not state; empty when the interface has no stretches).
  std::vector<std::uint16_t> gp_law, node_law;
  // The law of each Gauss point and node where it varies continuously along the line (a
  // rate-and-state taper or profile): the stretch's law with the taper and the profile
  // resolved there, once at set-up (derived from the spec, not state; empty otherwise, and
  // then gp_law / node_law decide).
  std::vector<CohesiveLaw> gp_point_law, node_point_law;
  // Rupture front (SCEC definition): the first time each node's slip rate exceeded
  // spec.rupture_slip_rate (or -1), s, and the largest slip rate it has had, m/s (on a fault:
  // the rate of the slip path, sliding only; else of the tangential jump).
  std::vector<double> node_rupture_time, node_peak_slip_rate;
  std::vector<double> node_slip_path;  // friction: the node's slip path D at the last step, m
  // The slip rate at the node over the last step, m/s: on a fault (Law::kSlipPathRate) the rate
  // friction sees, the slip path's (sliding only), signed as the tangential jump's increment;
  // elsewhere the tangential jump's rate (last_increment_t / dt).
  std::vector<double> node_slip_rate;
  std::vector<double> seg_fa_x, seg_fa_y, seg_fb_x, seg_fb_y;  // per-segment end forces (scratch)
  // Tributary tangent stiffness of each node at its current openings, N/m^2 per unit
  // thickness (sum over the Gauss points of its segments of weight x N x the law's largest
  // tangent eigenvalue): the cohesive part of the step bound (solver/time_step.hpp).
  std::vector<double> stiffness_node;
  std::vector<double> seg_ka, seg_kb;         // per-segment end stiffnesses (scratch)
  std::vector<FaceStencil> face_up, face_lo;  // this step's face stencils (derived, not state)
  // The fields of each node's upper and lower face (derived from spec.upper_faces / lower_faces,
  // not state; empty: spec.upper_field / lower_field for every node).
  std::vector<FaceFields> node_faces_up, node_faces_lo;
  FaceFields faces_up(std::size_t k) const {
    return node_faces_up.empty() ? FaceFields{std::uint8_t(spec.upper_field), 0, 1.0} : node_faces_up[k];
  }
  FaceFields faces_lo(std::size_t k) const {
    return node_faces_lo.empty() ? FaceFields{std::uint8_t(spec.lower_field), 0, 1.0} : node_faces_lo[k];
  }
  // Contact on light faces (solver/cohesive_step.cpp, light_face_scale): a face of less mass
  // than this, kg/m, has its contact penalty scaled by its mass over it. Set at set-up from the
  // case (a quarter of rho h^2 / 2, the face mass the set-up's step bound assumes; 0: none).
  double light_face_mass = 0.0;
  std::vector<double> jump_before;            // |jump| at the start of the step (scratch), m
  // Instability watch (solver/cohesive_step.cpp): the last step's jump increment per node, m,
  // for how many steps in a row the increment has reversed and grown, and its size when that
  // run of steps began, m.
  std::vector<double> last_increment_n, last_increment_t, streak_base;
  std::vector<std::int32_t> reversal_streak;
  double time = 0.0;  // s, the time of the tractions (the last evaluation)
  double work = 0.0;  // work done on the interface by the bodies so far, J/m (stored + dissipated)
  // Where its ties are laid (solver/tie_follow.hpp): the points sampled along spec's tied lines
  // (their reference positions, m) and the material's displacement there when the ties were last
  // laid, m; the same on every rank. Empty: laid where drawn.
  std::vector<double> tie_x0, tie_y0, tie_ux, tie_uy;
  // Distributed runs (parallel/halo.hpp): per node, 1 where this rank owns it (moves its faces,
  // evaluates the segments that touch it, loads the grid with its force) and where it knows it
  // (owned, or a ghost near its block whose faces and stiffness the owner sends every step);
  // `work` is then the work on the segments starting at owned nodes. Empty on one process.
  std::vector<unsigned char> rank_owned, rank_known;
  bool owns(std::size_t k) const { return rank_owned.empty() || rank_owned[k]; }
  bool knows(std::size_t k) const { return rank_known.empty() || rank_known[k]; }

  std::size_t num_nodes() const { return x0.size(); }
  std::size_t num_segments() const { return closed ? x0.size() : x0.size() - 1; }
  std::size_t segment_end(std::size_t seg) const {
    return closed && seg + 1 == x0.size() ? 0 : seg + 1;
  }
  double length() const { return closed ? s0.back() + seg_length.back() : s0.back(); }  // m
  // Jump of node k in its own frame (node_nx, node_ny).
  double jump_x(std::size_t k) const { return ux_up[k] - ux_lo[k]; }
  double jump_y(std::size_t k) const { return uy_up[k] - uy_lo[k]; }
  double jump_normal(std::size_t k) const {
    return node_nx[k] * jump_x(k) + node_ny[k] * jump_y(k);
  }
  double jump_tangential(std::size_t k) const {
    return node_ny[k] * jump_x(k) - node_nx[k] * jump_y(k);
  }
  // The node crack criterion (E10): a node has cracked once law.crack_measure(jumps) reaches
  // law.crack_threshold(separation_factor) (Xu-Needleman: |jump| >= 5 delta_t; bilinear:
  // effective opening lambda >= 1, full softening).
  // Energy stored in intact Gauss points (potential of the law), J/m. Distributed: the segments
  // this rank owns (those whose first node it owns, as collect_interface_state takes them), to
  // be summed over the ranks.
  double stored_energy() const;
};

// The interface's arrays of state (what the steps change), each listed once, in the checkpoint's
// order: for_each_interface_array(f) calls f(entry) for each. Per node, per Gauss point
// (segment-major, kGauss a segment) or per segment. Each entry says which of the operations over
// a whole interface carry it: kStored (the checkpoint, run/checkpoint.cpp), kGrown (a line that
// grows carries it over to its new numbering, cohesive/interface_growth.cpp), kGathered (a
// distributed run gathers the whole interface from the ranks owning its nodes,
// parallel/halo_interface.cpp collect_interface_state). What no entry lists is derived from the
// spec at set-up (geometry but x0, laws, faces), per-step scratch recomputed before it is read,
// or the ranks' bookkeeping (rank_owned, rank_known); time, work and the ties' points are the
// checkpoint's own entries.
enum class InterfaceExtent : unsigned char { node, gauss, segment };
enum InterfaceCarry : unsigned char { kStored = 1, kGrown = 2, kGathered = 4 };

template <class T>
struct InterfaceStateArray {
  using value_type = T;
  const char* name;
  std::vector<T> CohesiveInterface::*member;
  InterfaceExtent extent;
  unsigned char carry;  // InterfaceCarry flags
  constexpr bool has(InterfaceCarry c) const { return (carry & c) != 0; }
};

namespace interface_arrays_detail {
using E = InterfaceExtent;
using D = InterfaceStateArray<double>;
using CI = CohesiveInterface;
inline constexpr unsigned char kAll = kStored | kGrown | kGathered;
}  // namespace interface_arrays_detail

inline constexpr auto InterfaceArrays = [] {
  using namespace interface_arrays_detail;
  return std::make_tuple(
      // The reference node positions: stored so that a restore checks the grown line's.
      D{"x0", &CI::x0, E::node, kStored},
      D{"ux_up", &CI::ux_up, E::node, kAll}, D{"uy_up", &CI::uy_up, E::node, kAll},
      D{"ux_lo", &CI::ux_lo, E::node, kAll}, D{"uy_lo", &CI::uy_lo, E::node, kAll},
      D{"fx_node", &CI::fx_node, E::node, kAll}, D{"fy_node", &CI::fy_node, E::node, kAll},
      D{"node_crack_time", &CI::node_crack_time, E::node, kAll},
      D{"node_rupture_time", &CI::node_rupture_time, E::node, kAll},
      D{"node_peak_slip_rate", &CI::node_peak_slip_rate, E::node, kAll},
      D{"node_slip_path", &CI::node_slip_path, E::node, kAll},
      D{"node_slip_rate", &CI::node_slip_rate, E::node, kAll},
      D{"gp_dn", &CI::gp_dn, E::gauss, kAll}, D{"gp_dt", &CI::gp_dt, E::gauss, kAll},
      D{"gp_tn", &CI::gp_tn, E::gauss, kAll}, D{"gp_tt", &CI::gp_tt, E::gauss, kAll},
      InterfaceStateArray<std::uint8_t>{"gp_separated", &CI::gp_separated, E::gauss, kAll},
      D{"gp_damage", &CI::gp_damage, E::gauss, kAll}, D{"gp_slip", &CI::gp_slip, E::gauss, kAll},
      D{"gp_state", &CI::gp_state, E::gauss, kAll}, D{"gp_rate", &CI::gp_rate, E::gauss, kAll},
      D{"gp_normal", &CI::gp_normal, E::gauss, kAll},
      // The segments' end forces of the last evaluation (the next step's first force).
      D{"seg_fa_x", &CI::seg_fa_x, E::segment, kStored}, D{"seg_fa_y", &CI::seg_fa_y, E::segment, kStored},
      D{"seg_fb_x", &CI::seg_fb_x, E::segment, kStored}, D{"seg_fb_y", &CI::seg_fb_y, E::segment, kStored},
      D{"stiffness_node", &CI::stiffness_node, E::node, kAll},
      // The instability watch: each rank's own nodes (not gathered).
      D{"last_increment_n", &CI::last_increment_n, E::node, kStored | kGrown},
      D{"last_increment_t", &CI::last_increment_t, E::node, kStored | kGrown},
      D{"streak_base", &CI::streak_base, E::node, kStored | kGrown},
      InterfaceStateArray<std::int32_t>{"reversal_streak", &CI::reversal_streak, E::node, kStored | kGrown},
      // |jump| at the step's start: scratch, but read across a growth step and a gather.
      D{"jump_before", &CI::jump_before, E::node, kGrown | kGathered});
}();

template <class F>
constexpr void for_each_interface_array(F&& f) {
  std::apply([&](const auto&... entry) { (f(entry), ...); }, InterfaceArrays);
}


CohesiveInterface make_interface(const InterfaceSpec& spec);

// The fields of a face of node k (faces: spec.upper_faces or lower_faces, not empty): its part of
// the line is half of each segment beside it; where a change of field lies inside that part, the
// share of it before the change goes with the field before, the rest with the field after (a
// node on a T-junction: half and half). One change per node's part (the first).
FaceFields face_fields_at(const CohesiveInterface& c, const std::vector<FaceField>& faces, std::size_t k);

// Which law each Gauss point of `spec`'s line uses (0: the interface's, k: stretch k - 1), as
// make_interface assigns them, without making the interface (input checks of long lines);
// `visit` returns false to stop.
void for_each_gauss_point_law(const InterfaceSpec& spec, const std::function<bool(std::uint16_t)>& visit);

// The law of Gauss point i (or, with node_law, of node k): the interface's or its stretch's.
template <class Law>
const Law& law_of(const CohesiveInterface& c, const Law& base, std::uint16_t which) {
  return which == 0 ? base : std::get<Law>(c.spec.stretches[which - 1u].law);
}
// The law at Gauss point i (base: the interface's, of type Law): its point law, its stretch's,
// or the interface's.
template <class Law>
const Law& gauss_point_law(const CohesiveInterface& c, const Law& base, std::size_t i) {
  if (!c.gp_point_law.empty()) return std::get<Law>(c.gp_point_law[i]);
  return c.gp_law.empty() ? base : law_of(c, base, c.gp_law[i]);
}
// The same at node k.
template <class Law>
const Law& node_law_of(const CohesiveInterface& c, const Law& base, std::size_t k) {
  if (!c.node_point_law.empty()) return std::get<Law>(c.node_point_law[k]);
  return c.node_law.empty() ? base : law_of(c, base, c.node_law[k]);
}
inline const CohesiveLaw& node_law_variant(const CohesiveInterface& c, std::size_t k) {
  if (!c.node_point_law.empty()) return c.node_point_law[k];
  const std::uint16_t w = c.node_law.empty() ? 0 : c.node_law[k];
  return w == 0 ? c.spec.law : c.spec.stretches[w - 1u].law;
}

// The rate-and-state state psi at node k (dimensionless): the mean over the Gauss points next
// to it (the first of the segment after, the last of the one before, as the node's slip path),
// each its law's initial state plus its gp_state. 0 for any other law.
double node_state(const CohesiveInterface& c, std::size_t k);

// An opening small against the interface law's own scale (m): the instability watch's floor.
inline double opening_scale(const CohesiveLaw& law) {
  return std::visit([](const auto& l) { return l.opening_scale(); }, law);
}

}  // namespace rupture
