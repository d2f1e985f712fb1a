// rupture/solver/run_state.cpp
#include "solver/run_state.hpp"

#include <algorithm>

namespace rupture {

bool RunState::subcycled() const {
  return std::any_of(period.begin(), period.end(), [](int p) { return p > 1; });
}

bool RunState::holds_interfaces(int level) const {
  return std::find(interface_levels.begin(), interface_levels.end(), level) != interface_levels.end();
}

const Particles& all_particles(RunState& r) {
  if (!r.is_nested()) return r.levels[0].particles;
  if (r.merged_step != r.step) {  // once per step, whatever reads them
    r.merged.resize(0);
    for (const State& l : r.levels) r.merged.append_copy(l.particles);
    r.merged_step = r.step;
  }
  return r.merged;
}

std::size_t held_particles(const RunState& r) {
  std::size_t n = 0;
  for (const State& l : r.levels) n += l.particles.size();
  return n;
}

void collect_run_sums(RunState& r) {
  r.merged_step = -1;  // the particles may have changed (a split, a restore)
  if (!r.is_nested()) {  // one grid: its level is the run
    const State& s = r.levels[0];
    r.time = s.time, r.dt = s.dt, r.step = s.step;
    r.limits = s.limits;
    r.external_work = s.external_work, r.strain_work = s.strain_work;
    r.viscous_work = s.viscous_work;
    r.cohesive_seconds = s.cohesive_seconds;
    return;
  }
  r.external_work = r.strain_work = r.viscous_work = r.cohesive_seconds = 0.0;
  for (const State& l : r.levels) {
    r.external_work += l.external_work, r.strain_work += l.strain_work;
    r.viscous_work += l.viscous_work;
    r.cohesive_seconds += l.cohesive_seconds;
  }
}

}  // namespace rupture
