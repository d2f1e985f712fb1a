// rupture/output/history.hpp
// Energy history (theory E14), sampled at a fixed interval of simulated time. Units: s and J per
// unit thickness. The CSV is rewritten atomically, so it is always complete.
// Columns: time, kinetic_energy, strain_energy, external_work, total_energy, balance,
// relative_balance_error, cohesive_stored, cohesive_dissipated, where
// total = kinetic + strain + cohesive (stored + dissipated) and balance = initial + external
// work - total.
#pragma once
#include <string>
#include <vector>

namespace rupture {

struct EnergySample {
  double time, kinetic, strain, external_work, initial;
  double cohesive_stored = 0.0, cohesive_dissipated = 0.0;
  double viscous_dissipated = 0.0;  // Kelvin-Voigt damping's work, J (State::viscous_work)
  double total() const {
    return kinetic + strain + cohesive_stored + cohesive_dissipated + viscous_dissipated;
  }
  double balance() const { return initial + external_work - total(); }
  // |balance| relative to the energy put in: initial + |external work| + the energy a
  // prestressed fault releases (minus its work, when that is negative).
  double relative_error() const;
};

struct History {
  std::vector<EnergySample> samples;
  bool viscous = false;  // a damped material: csv() adds the viscous_dissipated column
  std::string csv() const;
  // Largest relative_error() of the samples at or after time `after` (s); the last sample's
  // if none is that late.
  double max_relative_error(double after) const;
  void write(const std::string& path) const;
};

}  // namespace rupture
