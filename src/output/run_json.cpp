// rupture/output/run_json.cpp
#include "output/run_json.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <toml++/toml.h>

#include "core/build_info.hpp"

namespace rupture {
namespace {
// JSON has no NaN/Inf; a failed run may carry them.
double finite(double v) { return std::isfinite(v) ? v : 0.0; }

// A quantity that may be absent ("none": never happened, not measured), which the summaries
// hold as -1 (the CLI lines keep that form): JSON null in run.json. TOML, whose tables build the
// record, has no null, so a marker string stands for it and becomes null after formatting.
constexpr const char* kNullMarker = "\x01null";
constexpr const char* kNullJson = "\"\\u0001null\"";  // the marker as the formatter writes it
template <class T>
void insert_or_null(toml::table& t, const std::string& key, T v) {
  if (!(v >= T(0)))  // negative (none) or NaN (not measured)
    t.insert(key, kNullMarker);
  else
    t.insert(key, v);
}
std::string with_nulls(std::string json) {
  for (std::size_t at = json.find(kNullJson); at != std::string::npos; at = json.find(kNullJson, at))
    json.replace(at, std::string(kNullJson).size(), "null");
  return json;
}
// A fault's rupture front (cohesive/rupture_front.hpp): one table per side of the patch.
toml::table side_table(const FrontSide& f) {
  toml::table t{{"nodes", f.nodes},
                {"speed", finite(f.speed)},
                {"peak_speed", finite(f.peak_speed)},
                {"triggered_windows", f.triggered},
                {"regime", f.regime}};
  insert_or_null(t, "leave_time", f.leave_time);
  insert_or_null(t, "reach_s", f.reach_s);
  insert_or_null(t, "supershear_s", f.supershear_s);
  insert_or_null(t, "supershear_time", f.supershear_time);
  return t;
}

toml::table front_table(const FrontSummary& f) {
  toml::table t{{"ruptured", f.ruptured},
                {"nucleation_overstressed", f.nucleation_overstressed},
                {"speed", finite(f.speed)},
                {"peak_speed", finite(f.peak_speed)},
                {"regime", f.regime},
                {"window_cells", kFrontWindowCells},
                {"definition", kFrontDefinition},
                {"forward", side_table(f.forward)},
                {"backward", side_table(f.backward)}};
  insert_or_null(t, "nucleation_begin_s", f.nucleation_begin_s);
  insert_or_null(t, "nucleation_end_s", f.nucleation_end_s);
  insert_or_null(t, "nucleation_time", f.nucleation_time);
  return t;
}
}  // namespace

std::string run_json(const Case& c, const CaseSummary& s, const RunRecord& r) {
  toml::table t;
  t.insert("version", RUPTURE_VERSION);
  const BuildInfo& build = build_info();  // which code made this run (core/build_info.hpp)
  t.insert("git_commit", build.commit);
  t.insert("git_dirty", build.dirty);
  t.insert("compiler", build.compiler);
  t.insert("build_type", build.build_type);
  t.insert("title", c.title);
  t.insert("status", r.status);
  t.insert("message", r.message);
  t.insert("stop_reason", r.stop_reason);
  t.insert("run_id", r.run_id);
  t.insert("case_hash", r.case_hash);
  toml::array warnings;  // what `rupture check` warned about (input/case_checks.hpp)
  for (const std::string& w : c.warnings) warnings.push_back(w);
  t.insert("warnings", warnings);
  t.insert("heartbeat", r.heartbeat);
  t.insert("heartbeat_unix", r.heartbeat_unix);
  insert_or_null(t, "checkpoint_time", r.checkpoint_time);
  insert_or_null(t, "checkpoint_step", r.checkpoint_step);
  t.insert("segments", r.segments);
  t.insert("dt", s.dt);
  t.insert("dt_cfl_limit", s.dt_cfl);
  t.insert("steps", r.steps);
  t.insert("steps_planned", s.steps);
  t.insert("end_time", c.time.end);
  t.insert("simulated_time", r.simulated_time);
  t.insert("cells", s.cells);
  t.insert("nodes", s.nodes);
  t.insert("fields", s.fields);
  t.insert("particles", s.particles);
  t.insert("memory_bytes_estimate", std::int64_t(s.memory_bytes));
  t.insert("threads", r.threads);
  t.insert("ranks", r.ranks);
  t.insert("scheme", scheme_name(c.solver.scheme));
  t.insert("flip", c.solver.flip);
  t.insert("mass", c.solver.mass == MassMatrix::averaged ? "averaged" : "lumped");
  t.insert("wall_seconds", r.wall_seconds);
  t.insert("cohesive_seconds", r.cohesive_seconds);
  t.insert("growth_seconds", r.growth_seconds);
  t.insert("particle_updates_per_second", finite(r.particle_updates_per_second));
  toml::table speeds;
  for (std::size_t k = 0; k < c.materials.size(); ++k) {
    const WaveSpeeds& w = s.speeds[k];
    speeds.insert(c.materials[k].name,
                  toml::table{{"dilatational", w.dilatational},
                              {"shear", w.shear},
                              {"rayleigh", w.rayleigh},
                              {"rayleigh_approx", w.rayleigh_approx}});
  }
  t.insert("wave_speeds", speeds);
  t.insert("energy", toml::table{{"kinetic", finite(r.kinetic_energy)},
                                 {"strain", finite(r.strain_energy)},
                                 {"external_work", finite(r.external_work)}});
  t.insert("energy_balance_error", finite(r.energy_balance_error));
  t.insert("energy_balance_error_final", finite(r.energy_balance_error_final));
  t.insert("dt_bulk_limit", s.dt_bulk);
  t.insert("dt_cohesive_limit", s.dt_cohesive);
  if (std::isfinite(r.min_cohesive_dt)) t.insert("dt_cohesive_limit_min", r.min_cohesive_dt);
  t.insert("cohesive_safety", c.time.cohesive_safety);
  t.insert("subcycling", c.time.subcycling == Subcycling::levels ? "levels" : "none");
  if (!r.cracks.empty()) {
    toml::array all;
    for (std::size_t k = 0; k < r.cracks.size(); ++k) {
      const CrackSummary& cs = r.cracks[k];
      toml::table ct{{"interface", c.interface_names[k]},
                     {"initiated", cs.initiated},
                     {"sustained_speed", finite(cs.sustained_speed)},
                     {"peak_speed", finite(cs.peak_speed)},
                     {"final_tip", cs.final_tip},
                     {"final_cohesive_zone_length", cs.final_cohesive_zone},
                     {"final_traction_zone_length", cs.final_traction_zone},
                     {"cohesive_zone_definition", CrackTracker::kCohesiveZoneDefinition},
                     {"traction_zone_definition", CrackTracker::kTractionZoneDefinition},
                     {"final_tip_y", cs.final_tip_y},
                     {"final_tip_s", cs.final_tip_s},
                     {"back_speed", finite(cs.back_speed)},
                     {"last_window_speed", finite(cs.last_window_speed)},
                     {"arrested", cs.arrested},
                     {"mach_readings", cs.mach_readings},
                     {"upper_body", c.bodies[std::size_t(c.interfaces[k].upper_body)].name},
                     {"lower_body", c.bodies[std::size_t(c.interfaces[k].lower_body)].name},
                     {"regime", cs.regime}};
      // Faces that change body along the line (a T-junction): [[from (m), body], ...] per side.
      const bool now = k < r.faces.size();
      for (const auto& [key, list] : {std::pair{"upper_faces", now ? &r.faces[k][0] : &c.interfaces[k].upper_faces},
                                      std::pair{"lower_faces", now ? &r.faces[k][1] : &c.interfaces[k].lower_faces}}) {
        if (list->empty()) continue;
        toml::array a;
        for (const FaceField& f : *list) a.push_back(toml::array{f.from, c.bodies[std::size_t(f.body)].name});
        ct.insert(key, a);
      }
      // Absent values (-1 in the summaries: never, not measured) as null.
      insert_or_null(ct, "initiation_time", cs.initiation_time);
      insert_or_null(ct, "intersonic_time", cs.intersonic_time);
      insert_or_null(ct, "daughter_crack_time", cs.daughter_time);
      insert_or_null(ct, "end_reached_time", cs.end_reached_time);
      insert_or_null(ct, "initiation_s", cs.initiation_s);
      insert_or_null(ct, "steady_begin", cs.steady_begin);
      insert_or_null(ct, "steady_end", cs.steady_end);
      insert_or_null(ct, "arrest_time", cs.arrest_time);
      insert_or_null(ct, "arrest_s", cs.arrest_s);
      insert_or_null(ct, "mach_angle", cs.mach_angle);
      insert_or_null(ct, "mach_angle_spread", cs.mach_angle_spread);
      insert_or_null(ct, "mach_angle_left", cs.mach_angle_left);
      insert_or_null(ct, "mach_angle_right", cs.mach_angle_right);
      insert_or_null(ct, "mach_speed", cs.mach_speed);
      // Speeds against the wave speeds of both adjoining materials (a bimaterial interface has two).
      for (const char* side : {"upper", "lower"}) {
        const InterfaceSpec& is = c.interfaces[k];
        const int body = std::string(side) == "upper" ? is.upper_body : is.lower_body;
        const WaveSpeeds& w = s.speeds[std::size_t(c.bodies[std::size_t(body)].material)];
        const std::string p = std::string("sustained_speed_over_");
        ct.insert(p + "cR_" + side, finite(cs.sustained_speed / w.rayleigh));
        ct.insert(p + "cS_" + side, finite(cs.sustained_speed / w.shear));
        ct.insert(p + "cD_" + side, finite(cs.sustained_speed / w.dilatational));
        if (cs.fault) {  // the front's speed against both sides too
          ct.insert(std::string("front_speed_over_cS_") + side, finite(cs.front.speed / w.shear));
          ct.insert(std::string("front_speed_over_cR_") + side, finite(cs.front.speed / w.rayleigh));
        }
      }
      // Which material the single ratios and the regimes are against (the lower body's).
      ct.insert("speed_ratio_material",
                c.materials[std::size_t(c.bodies[std::size_t(c.interfaces[k].lower_body)].material)].name);
      if (cs.fault) ct.insert("front", front_table(cs.front));
      if (cs.grows) {  // a growing crack (solver/crack_growth.hpp), also as flat cracks.NAME.KEY
        ct.insert_or_assign("initial_angle", cs.initial_angle);
        ct.insert_or_assign("branches", cs.branches);
        ct.insert_or_assign("length", cs.grown_length);
        const std::string p = "cracks." + c.interface_names[k] + ".";
        insert_or_null(t, p + "initiation_time", cs.initiated ? cs.initiation_time : -1.0);
        t.insert(p + "initial_angle", cs.initial_angle);
        t.insert(p + "branches", cs.branches);
        t.insert(p + "length", cs.grown_length);
        if (cs.nucleates) {  // when the drawn line came loose (null: it stayed intact)
          ct.insert_or_assign("nucleation_time", cs.nucleation_time);
          insert_or_null(t, p + "nucleation_time", cs.nucleation_time);
        }
      }
      if (k == 0) {
        t.insert("crack", ct);
        for (auto&& [key, value] : ct) t.insert("crack." + std::string(key.str()), value);
      }
      all.push_back(ct);
    }
    t.insert("cracks", all);
  }
  t.insert("energy_cohesive", toml::table{{"stored", finite(r.cohesive_stored)},
                                          {"dissipated", finite(r.cohesive_dissipated)}});
  toml::table input;
  try {
    input = toml::parse(c.input_toml);
  } catch (const toml::parse_error&) {
    // The echo was produced by toml++ itself; keep run.json writable regardless.
  }
  t.insert("input", input);
  std::ostringstream os;
  os << toml::json_formatter{t} << "\n";
  return with_nulls(os.str());
}

std::string recorded_run_id(const std::string& dir) {
  std::ifstream in(dir + "/run.json");
  if (!in) return {};
  const std::string key = "\"run_id\"";
  for (std::string line; std::getline(in, line);) {
    const auto at = line.find(key);
    if (at == std::string::npos) continue;
    const auto open = line.find('"', line.find(':', at + key.size()));
    const auto close = open == std::string::npos ? open : line.find('"', open + 1);
    if (close == std::string::npos) return {};
    return line.substr(open + 1, close - open - 1);
  }
  return {};
}

}  // namespace rupture
