// rupture/cohesive/fault_profile.hpp
// Tabulated rate-and-state parameters along a fault ([interface.NAME.profile]): a, b, Dc and
// V_w each as a table of (coordinate, value) points, piecewise linear in one coordinate of the
// reference position (x, y, or the arc length s from the line's start), constant beyond the
// first and last points. The interface resolves them once, at set-up, into the law of every
// Gauss point and node (cohesive/interface.hpp point laws), with the initial state re-balanced
// against the initial traction there; nothing of it runs in the step. Units: m, m/s.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "cohesive/rate_state.hpp"

namespace rupture {

// One parameter's table: coordinates strictly increasing, at least two points (or none: off).
struct ProfileTable {
  std::vector<double> at, value;
  bool on() const { return !at.empty(); }
  // The value at coordinate u: linear between the two points around it, the end value beyond.
  double operator()(double u) const;
};

enum class ProfileAxis : std::uint8_t { x, y, s };

struct RateStateProfile {
  ProfileAxis along = ProfileAxis::x;
  ProfileTable a, b, dc, vw;  // vw: weakening_slip_rate (flash_heating)
  bool on() const { return a.on() || b.on() || dc.on() || vw.on(); }
  // `law` at the point (x, y) at arc length s: the tabulated parameters replaced and the
  // initial state balancing the initial traction with them (RateStateFriction::
  // initialize_state). Untabulated parameters stay as they are.
  RateStateFriction apply(RateStateFriction law, double x, double y, double s) const;
  // `rupture check`'s words: ", profile along x of a (N points), ..." ("" when off).
  std::string describe() const;
};

const char* axis_name(ProfileAxis a);  // "x", "y", "s"

}  // namespace rupture
