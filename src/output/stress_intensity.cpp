// rupture/output/stress_intensity.cpp
#include "output/stress_intensity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/atomic_file.hpp"
#include "solver/crack_tips.hpp"
#include "solver/run_state.hpp"

namespace rupture {

namespace {

// The point at arc length s along the interface's nodes and the line's direction there.
TipFrame along_line(const CohesiveInterface& in, double s) {
  const std::vector<double>& s0 = in.s0;
  const std::size_t n = s0.size();
  std::size_t k = std::size_t(std::upper_bound(s0.begin(), s0.end(), s) - s0.begin());
  k = std::clamp<std::size_t>(k == 0 ? 0 : k - 1, 0, n - 2);  // segment k: nodes k, k + 1
  const double len = s0[k + 1] - s0[k], f = len > 0 ? std::clamp((s - s0[k]) / len, 0.0, 1.0) : 0.0;
  TipFrame t;
  t.x = in.x0[k] + f * (in.x0[k + 1] - in.x0[k]);
  t.y = in.y0[k] + f * (in.y0[k + 1] - in.y0[k]);
  t.e1x = in.seg_ny[k], t.e1y = -in.seg_nx[k];  // the tangent (n_y, -n_x): along +s
  return t;
}

}  // namespace

std::vector<TipFrame> crack_tips(const Case& c, const RunState& s, std::size_t k,
                                 const CrackTracker& tracker) {
  const CohesiveInterface& in = s.interface(k);
  std::vector<TipFrame> tips;
  const InterfaceSpec& is = c.interfaces[k];
  if (!is.precracked && !is.drawn_open && !is.growth.on()) {  // a cohesive line's running tip
    const double at = tracker.samples().empty() ? 0.0 : tracker.samples().back().tip;
    tips.push_back(along_line(in, at));
    return tips;
  }
  // The interface's own line: the one drawn, or grown (solver/crack_growth.hpp).
  const double h = s.levels[std::size_t(s.interface_levels[k])].grid.cell_size();
  for (const CrackTip& t : precrack_tips(in.spec, 1e-6 * h, c.interfaces[k].j_domains.back() * h))
    tips.push_back(t.frame);
  return tips;
}

void sample_stress_intensity(const Case& c, RunState& s, const std::vector<CrackTracker>& trackers,
                             const std::vector<CrackGrowthRecord>& growth, std::vector<TipSeries>& series) {
  series.resize(c.interfaces.size());
  for (std::size_t k = 0; k < c.interfaces.size(); ++k) {
    const InterfaceSpec& is = c.interfaces[k];
    if (!is.stress_intensity) continue;
    // A line not yet loose is intact material: no tip to read (solver/crack_nucleation.hpp).
    if (is.nucleation_strength > 0.0 && (k >= growth.size() || !growth[k].nucleated())) continue;
    const State& L = s.levels[std::size_t(s.interface_levels[k])];
    const TipMaterial mat = tip_material(c, k);
    const std::vector<InitialStrain> initial = initial_field_strains(c);
    const std::vector<TipFrame> tips = crack_tips(c, s, k, trackers[k]);
    const double h = L.grid.cell_size();
    // A growing tip's speed: its label and end as growth records them (the drawn line's tips).
    std::vector<CrackTip> ends;
    const double window = is.j_domains.back() * h;
    if (is.growth.on() && k < growth.size()) ends = precrack_tips(s.interface(k).spec, 1e-6 * h, window);
    for (std::size_t t = 0; t < tips.size(); ++t) {
      const bool grows = t < ends.size();
      const TipMaterial m = grows ? growing_tip_material(c, k, growth[k], int(t), ends[t].end, s.time, window) : mat;
      const double speed = grows ? growing_tip_speed(c, k, growth[k], int(t), ends[t].end, s.time, window) : 0.0;
      const std::vector<TipIntegrals> r = read_tip(L, s.interface(k), is, tips[t], m, s.time, initial);
      for (std::size_t d = 0; d < r.size(); ++d)
        series[k].rows.insert(series[k].rows.end(),
                              {s.time, double(t), tips[t].x, tips[t].y, is.j_domains[d] * h, r[d].J,
                               r[d].K_I, r[d].K_II, double(r[d].points), speed});
    }
  }
}

void write_stress_intensity(const std::string& dir, const Case& c,
                            const std::vector<TipSeries>& series) {
  for (std::size_t k = 0; k < c.interfaces.size() && k < series.size(); ++k) {
    if (!c.interfaces[k].stress_intensity) continue;
    std::string out = "time,tip,x,y,domain,J,K_I,K_II,points,speed\n";
    const std::vector<double>& r = series[k].rows;
    for (std::size_t i = 0; i + kTipColumns <= r.size(); i += kTipColumns)
      out += fmt::format("{:.9e},{:d},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:d},{:.6g}\n", r[i],
                         int(r[i + 1]), r[i + 2], r[i + 3], r[i + 4], r[i + 5], r[i + 6], r[i + 7],
                         long(r[i + 8]), r[i + 9]);
    write_file_atomic(dir + "/stress_intensity_" + c.interface_names[k] + ".csv", out);
  }
}

void write_crack_paths(const std::string& dir, const Case& c,
                       const std::vector<CrackGrowthRecord>& growth) {
  for (std::size_t k = 0; k < c.interfaces.size() && k < growth.size(); ++k) {
    if (!c.interfaces[k].growth.on()) continue;
    std::string out = "time,tip,end,x,y,angle,length,K_I,K_II,speed\n";
    const std::vector<GrowthRow>& r = growth[k].rows;
    // speed: the tip's when the row was made (solver/crack_growth.hpp, tip_speed: over the outer
    // J domain's radius of path, as the branching criterion reads it; 0 until it has grown that far).
    const double window = c.interfaces[k].j_domains.back() * c.grid.cell_size;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const GrowthRow& w = r[i];
      const double v = tip_speed(growth[k], w.tip, w.end, w.time, window, i + (w.split ? 0 : 1));
      out += fmt::format("{:.9e},{:d},{:d},{:.9e},{:.9e},{:.6f},{:.9e},{:.9e},{:.9e},{:.6g}\n", w.time, w.tip,
                         w.end_code(), w.x, w.y, w.angle, w.length, w.K_I, w.K_II, v);
    }
    write_file_atomic(dir + "/crack_path_" + c.interface_names[k] + ".csv", out);
  }
}

}  // namespace rupture
