// rupture/output/history.cpp
#include "output/history.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/atomic_file.hpp"

namespace rupture {

double EnergySample::relative_error() const {
  // A prestressed fault puts energy in through its negative work (the stress drop).
  const double released = std::max(0.0, -(cohesive_stored + cohesive_dissipated));
  const double scale = initial + std::fabs(external_work) + released;
  return scale > 0.0 ? std::fabs(balance()) / scale : 0.0;
}

double History::max_relative_error(double after) const {
  double worst = 0.0;
  bool any = false;
  for (const EnergySample& e : samples)
    if (e.time >= after) worst = std::max(worst, e.relative_error()), any = true;
  return any || samples.empty() ? worst : samples.back().relative_error();
}

std::string History::csv() const {
  std::string s =
      "time,kinetic_energy,strain_energy,external_work,total_energy,balance,"
      "relative_balance_error,cohesive_stored,cohesive_dissipated";
  s += viscous ? ",viscous_dissipated\n" : "\n";
  for (const EnergySample& e : samples) {
    s += fmt::format("{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.6e},{:.9e},{:.9e}", e.time,
                     e.kinetic, e.strain, e.external_work, e.total(), e.balance(),
                     e.relative_error(), e.cohesive_stored, e.cohesive_dissipated);
    s += viscous ? fmt::format(",{:.9e}\n", e.viscous_dissipated) : "\n";
  }
  return s;
}

void History::write(const std::string& path) const { write_file_atomic(path, csv()); }

}  // namespace rupture
