// rupture/cohesive/fault_profile.cpp: interpolation in the tables of a rate-and-state profile
// and the law they give at a point.
#include "cohesive/fault_profile.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace rupture {

double ProfileTable::operator()(double u) const {
  if (u <= at.front()) return value.front();
  if (u >= at.back()) return value.back();
  const std::size_t k = std::size_t(std::upper_bound(at.begin(), at.end(), u) - at.begin());  // at[k-1] <= u < at[k]
  const double f = (u - at[k - 1]) / (at[k] - at[k - 1]);
  return value[k - 1] + f * (value[k] - value[k - 1]);
}

const char* axis_name(ProfileAxis a) {
  switch (a) {
    case ProfileAxis::x:
      return "x";
    case ProfileAxis::y:
      return "y";
    case ProfileAxis::s:
      return "s";
  }
  return "?";
}

RateStateFriction RateStateProfile::apply(RateStateFriction law, double x, double y, double s) const {
  if (!on()) return law;
  const double u = along == ProfileAxis::x ? x : along == ProfileAxis::y ? y : s;
  if (a.on()) law.a = a(u);
  if (b.on()) law.b = b(u);
  if (dc.on()) law.dc = dc(u);
  if (vw.on()) law.vw = vw(u);
  law.initialize_state();
  return law;
}

std::string RateStateProfile::describe() const {
  if (!on()) return "";
  std::string s = fmt::format(", profile along {} of", axis_name(along));
  const char* sep = " ";
  for (const auto& [name, t] : {std::pair<const char*, const ProfileTable*>{"a", &a}, {"b", &b},
                                {"dc", &dc}, {"weakening_slip_rate", &vw}})
    if (t->on()) s += fmt::format("{}{} ({} points)", sep, name, t->at.size()), sep = ", ";
  return s;
}

}  // namespace rupture
