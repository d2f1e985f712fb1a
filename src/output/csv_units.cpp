// rupture/output/csv_units.cpp
#include "output/csv_units.hpp"

#include "core/atomic_file.hpp"

namespace rupture {

const std::vector<CsvColumn>& csv_columns() {
  static const std::vector<CsvColumn> columns = {
      // output/history.cpp (theory E14), per unit thickness
      {"history.csv", "time", "s", "simulated time"},
      {"history.csv", "kinetic_energy", "J/m", "sum 1/2 m v^2 of the particles"},
      {"history.csv", "strain_energy", "J/m", "stored stress work (solver/energy.hpp)"},
      {"history.csv", "external_work", "J/m", "work of prescribed velocities and loads"},
      {"history.csv", "total_energy", "J/m", "kinetic + strain + cohesive stored + dissipated"},
      {"history.csv", "balance", "J/m", "external work + initial energy - total energy"},
      {"history.csv", "relative_balance_error", "-", "|balance| / (initial energy + |external work|)"},
      {"history.csv", "cohesive_stored", "J/m", "recoverable energy in the cohesive interfaces"},
      {"history.csv", "cohesive_dissipated", "J/m", "work on the interfaces not stored in them"},
      // cohesive/crack_tip.cpp (theory E10, E11)
      {"crack_tip*.csv", "time", "s", "sample time"},
      {"crack_tip*.csv", "tip_x", "m", "x of the tip (E10: jump 5 delta_t)"},
      {"crack_tip*.csv", "speed", "m/s", "E11 speed (31-sample least squares); nan at the ends"},
      {"crack_tip*.csv", "speed_over_cR", "-", "speed / c_R of the lower body's material"},
      {"crack_tip*.csv", "speed_over_cS", "-", "speed / c_S of the lower body's material"},
      {"crack_tip*.csv", "stretches", "", "number of separated stretches"},
      {"crack_tip*.csv", "cohesive_zone_length", "m", "softening zone: tip to the last node past the peak-traction opening"},
      {"crack_tip*.csv", "leading_stretch_begin", "m", "x where the leading separated stretch begins"},
      {"crack_tip*.csv", "leading_stretch_end", "m", "x where the leading separated stretch ends"},
      {"crack_tip*.csv", "traction_zone_length", "m", "loaded zone: tip forward while traction >= 10 % of the peak"},
      {"crack_tip*.csv", "tip_y", "m", "y of the tip"},
      {"crack_tip*.csv", "tip_s", "m", "arc length of the tip along the interface"},
      {"crack_tip*.csv", "back_s", "m", "arc length where the tip's stretch begins"},
      {"crack_tip*.csv", "back_x", "m", "x of that point"},
      {"crack_tip*.csv", "back_y", "m", "y of that point"},
      {"crack_tip*.csv", "back_speed", "m/s", "E11 speed of the back tip (> 0 towards the line's start)"},
      {"crack_stretches*.csv", "time", "s", "sample time"},
      {"crack_stretches*.csv", "index", "", "stretch number along the line"},
      {"crack_stretches*.csv", "x_begin", "m", "x where the stretch begins"},
      {"crack_stretches*.csv", "x_end", "m", "x where it ends"},
      {"crack_stretches*.csv", "y_begin", "m", "y where it begins"},
      {"crack_stretches*.csv", "y_end", "m", "y where it ends"},
      {"crack_stretches*.csv", "s_begin", "m", "arc length where it begins"},
      {"crack_stretches*.csv", "s_end", "m", "arc length where it ends"},
      {"rupture_time_*.csv", "s", "m", "arc length of the interface node"},
      {"rupture_time_*.csv", "x", "m", "x of the node"},
      {"rupture_time_*.csv", "y", "m", "y of the node"},
      {"rupture_time_*.csv", "crack_time", "s", "when its jump reached the law's crack criterion (Xu-Needleman: 5 delta_t; bilinear: full softening; slip weakening: slip Dc) (-1: not yet)"},
      {"rupture_time_*.csv", "rupture_time", "s", "first time its slip rate exceeded interface.rupture_slip_rate (1 mm/s; -1: not yet)"},
      {"rupture_time_*.csv", "peak_slip_rate", "m/s", "largest slip rate so far"},
      {"rupture_time_*.csv", "slip", "m", "tangential jump now"},
      {"rupture_time_*.csv", "opening", "m", "normal jump now"},
      {"stations/*.csv", "time", "s", "sample time"},
      {"stations/*.csv", "slip", "m", "fault station: tangential jump"},
      {"stations/*.csv", "slip_rate", "m/s", "fault station: the slip rate friction sees (a fault's slip path rate over the last step, signed as the jump; elsewhere the jump's rate)"},
      {"stations/*.csv", "opening", "m", "fault station: normal jump"},
      {"stations/*.csv", "shear_traction", "Pa", "fault station: total shear traction (prestress included)"},
      {"stations/*.csv", "normal_traction", "Pa", "fault station: total normal traction, tension positive"},
      {"stations/*.csv", "x", "m", "body station: the particle's position"},
      {"stations/*.csv", "y", "m", "body station: the particle's position"},
      {"stations/*.csv", "vx", "m/s", "body station: the particle's velocity"},
      {"stations/*.csv", "vy", "m/s", "body station: the particle's velocity"},
      {"stations/*.csv", "ux", "m", "body station: the particle's displacement since t = 0"},
      {"stations/*.csv", "uy", "m", "body station: the particle's displacement since t = 0"},
      {"stations/*.csv", "jump_rate", "m/s", "fault station: the last step's tangential jump increment over its dt (the stick spring's elastic jump included)"},
      // solver/crack_growth.hpp: the paths of growing cracks
      {"crack_path_*.csv", "time", "s", "when the segment was made (or the tip split)"},
      {"crack_path_*.csv", "tip", "-", "the crack's tip (0, 1: its own; 2, 3, ...: a branch's)"},
      {"crack_path_*.csv", "end", "-", "0, 1: a segment at the line's start, end; 2, 3: the tip there split"},
      {"crack_path_*.csv", "x", "m", "the new vertex (a split: the tip), reference position"},
      {"crack_path_*.csv", "y", "m", "the new vertex (a split: the tip), reference position"},
      {"crack_path_*.csv", "angle", "deg", "from the crack's direction to the segment (a split: the half angle)"},
      {"crack_path_*.csv", "length", "m", "of the segment (a split: 0)"},
      {"crack_path_*.csv", "K_I", "Pa m^1/2", "what the criterion read"},
      {"crack_path_*.csv", "K_II", "Pa m^1/2", "what the criterion read"},
      {"crack_path_*.csv", "speed", "m/s", "the tip's speed over the outer J domain's radius of path (0 until it grew that far)"},
      // cohesive/mach_angle.cpp (theory E12)
      {"mach_angle*.csv", "time", "s", "reading time"},
      {"mach_angle*.csv", "tip_x", "m", "x of the tip"},
      {"mach_angle*.csv", "tip_y", "m", "y of the tip"},
      {"mach_angle*.csv", "e11_speed", "m/s", "latest E11 speed at or before the reading"},
      {"mach_angle*.csv", "angle_left", "degree", "Mach angle left of the running direction"},
      {"mach_angle*.csv", "angle_left_error", "degree", "its standard error (fit scatter)"},
      {"mach_angle*.csv", "implied_speed_left", "m/s", "c_S / sin(angle_left)"},
      {"mach_angle*.csv", "jump_left", "Pa", "mean tau_max jump across the front"},
      {"mach_angle*.csv", "origin_left", "m", "where the front meets the crack line, from the tip along the crack"},
      {"mach_angle*.csv", "angle_right", "degree", "Mach angle right of the running direction"},
      {"mach_angle*.csv", "angle_right_error", "degree", "its standard error (fit scatter)"},
      {"mach_angle*.csv", "implied_speed_right", "m/s", "c_S / sin(angle_right)"},
      {"mach_angle*.csv", "jump_right", "Pa", "mean tau_max jump across the front"},
      {"mach_angle*.csv", "origin_right", "m", "where the front meets the crack line, from the tip along the crack"},
      {"mach_angle*.csv", "dir_x", "-", "unit vector along the crack (running direction), x"},
      {"mach_angle*.csv", "dir_y", "-", "unit vector along the crack (running direction), y"},
      // output/interface_csv.cpp (the paper's Fig. 12)
      {"interface/*.csv", "time", "s", "profile time"},
      {"interface/*.csv", "x", "m", "x of the cohesive node (reference position)"},
      {"interface/*.csv", "jump_n", "m", "normal opening (E7)"},
      {"interface/*.csv", "jump_t", "m", "tangential sliding (E7)"},
      {"interface/*.csv", "traction_n", "Pa", "normal cohesive traction (E8)"},
      {"interface/*.csv", "traction_t", "Pa", "tangential cohesive traction (E8)"},
      {"interface/*.csv", "force_x", "N/m", "nodal cohesive force, x (E9)"},
      {"interface/*.csv", "force_y", "N/m", "nodal cohesive force, y (E9)"},
      {"interface/*.csv", "y_upper", "m", "deformed y of the upper face"},
      {"interface/*.csv", "y_lower", "m", "deformed y of the lower face"},
      {"interface/*.csv", "cracked", "", "1 once the jump reached 5 delta_t"},
      {"interface/*.csv", "y", "m", "y of the node (reference position)"},
      {"interface/*.csv", "s", "m", "arc length of the node"},
      {"interface/*.csv", "x_upper", "m", "deformed x of the upper face"},
      {"interface/*.csv", "x_lower", "m", "deformed x of the lower face"},
  };
  return columns;
}

void write_csv_units(const std::string& dir) {
  std::string out = "file,column,unit,meaning\n";
  for (const CsvColumn& c : csv_columns()) {
    out += c.file;
    out += ',';
    out += c.column;
    out += ',';
    out += c.unit;
    out += ",\"";
    out += c.meaning;
    out += "\"\n";
  }
  write_file_atomic(dir + "/units.csv", out);
}

}  // namespace rupture
