// rupture/input/case_parse.hpp
// One parse function per table of the input file (input/case_toml builds the Case by calling them
// in order). Each validates its table completely; cross-table rules that need several tables
// live in input/case_checks. Internal to input/.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "input/case.hpp"
#include "input/toml_section.hpp"

namespace rupture {

// Names already parsed, for the tables that refer to them.
struct ParseContext {
  std::map<std::string, int> material_index;
  // The bodies (indices into Case::bodies) each name stands for: a body's own index; once a
  // line inside it has split it (input/parse_body_split.cpp), all its parts, so a boundary
  // condition or load naming it acts on every part. The parts' own names (NAME.below.IFACE,
  // NAME.inside.IFACE) and the name of the part that keeps NAME's index (NAME.above.IFACE,
  // NAME.outside.IFACE) stand for the parts made by that split.
  std::map<std::string, std::vector<int>> body_parts;
  std::string case_dir;  // directory of the case file: relative table_file paths start there
  // Tables read from files (table_file), so the input echo can hold them inline.
  struct FileTable {
    std::vector<std::string> path;  // keys of the table holding table_file, e.g. {"loads", "x"}
    std::vector<double> t, v;
  };
  std::vector<FileTable> file_tables;
};

void parse_model(Section& top, Case& c);
void parse_materials(Section& top, Case& c, ParseContext& ctx);
void parse_grid(Section& top, Case& c);
void parse_bodies(Section& top, Case& c, ParseContext& ctx);
void parse_time(Section& top, Case& c);
void parse_solver(Section& top, Case& c);
void parse_boundary(Section& top, Case& c, ParseContext& ctx);
void parse_absorbing(Section& top, Case& c);  // after parse_boundary
void parse_stations(Section& top, Case& c);   // after parse_interfaces
// law = "slip_weakening" keys of an [interface] table into is.law, its stretches (input/parse_fault.cpp).
void parse_fault_law(Section& f, const Case& c, InterfaceSpec& is);
// law = "rate_state" keys of an [interface] table into is.law, its stretches (input/parse_fault.cpp).
void parse_rate_state_law(Section& f, const Case& c, InterfaceSpec& is);
// The contact of separated points (cohesive/contact.hpp) from the keys contact, friction,
// contact_stiffness and contact_tangential_stiffness into is.contact and is.contact_law
// (input/parse_interfaces.cpp), for a law's parser (input/law_registry.hpp). default_stiffness:
// the law's own penalty, Pa/m, the default contact_stiffness. contact_only: law = "contact", a
// pre-crack: contact defaults to true and must be, and contact_stiffness is required.
void parse_separated_contact(Section& f, InterfaceSpec& is, double default_stiffness,
                             bool contact_only);
// The penalties' default where a law has none of its own (faults' normal_stiffness and
// stick_stiffness, law = "contact"'s contact_stiffness): the stiffness of one cell of the stiffer
// adjoining body, M / h (M = lambda + 2 mu, the P-wave modulus; h the smallest cell), Pa/m.
// The penalty's spurious compliance is then that of a layer one cell thick: an O(h) error that
// vanishes with the grid, and the interface's stability limit stays near the bulk's
// (docs/cohesive_laws.md). is: its bodies set.
double cell_penalty_stiffness(const Case& c, const InterfaceSpec& is);
// A law's validate() message "name = value: rule" as the input error of its key (`keys` maps a
// parameter name to its input key where they differ); nothing if `problem` is empty.
void fail_on_invalid(Section& f, const std::string& problem,
                     const std::map<std::string, std::string>& keys);
void parse_interfaces(Section& top, Case& c, ParseContext& ctx);
// The crack keys of an [interface] table (input/parse_crack_growth.cpp), in this order, after the
// law and geometry: drawn_open; stress_intensity and j_domains; growth and its parameters,
// branching; nucleation; the fields the branches' wedges will take (NAME.branchK, appended to
// c's fields).
void parse_drawn_open(Section& f, InterfaceSpec& is);
void parse_stress_intensity(Section& f, InterfaceSpec& is);
void parse_growth(Section& f, InterfaceSpec& is, const Case& c);
void parse_nucleation(Section& f, InterfaceSpec& is);
void reserve_branch_fields(Section& f, InterfaceSpec& is, Case& c, const std::string& name);
// The bodies the name `s.key(key)` stands for (ParseContext::body_parts); an unknown name is an
// InputError listing the names allowed, with the nearest as a hint.
const std::vector<int>& named_bodies(Section& s, const std::string& key, const std::string& name,
                                     const Case& c, const ParseContext& ctx);
// The one body the string at `key` names (an interface's upper_body, lower_body): a name that
// stands for several parts of a split body is an InputError naming the parts.
int single_body(Section& s, const std::string& key, const Case& c, const ParseContext& ctx);

// An interface's line as parse_interface_geometry read it: the key it was given by ("y",
// "points", "center"), and for the circle form the circle itself (its polygon lies inside the
// circle by up to `slack`, m).
struct InterfaceLine {
  std::string key;
  double slack = 0.0;
  bool circle = false;
  double center[2]{}, radius = 0.0;
};
// interface.NAME.body: splits that body (or the part of it holding the line) along the line,
// adds the new part to c.bodies right after it, with a field of its own, ties the line's
// extensions to the body's edge, and sets the interface's bodies, fields and bonded lines
// (docs/interfaces.md). Earlier interfaces whose face lies on the new part move to it.
void split_body_along_interface(Section& f, InterfaceSpec& is, Case& c, ParseContext& ctx,
                                const std::string& name, const InterfaceLine& line);
// Numbers the velocity fields in order of first appearance among the bodies (Case::field_names)
// and updates the bodies and interfaces; a no-op when they already are.
void renumber_fields(Case& c);
void parse_loads(Section& top, Case& c, ParseContext& ctx);
// `function` and its keys (input/parse_time_function.cpp). value_key names the amplitude key
// ("velocity"); empty: the function is a dimensionless factor (value 1). path: the keys of the
// table b, recorded with a table read from a file.
TimeFunction parse_time_function(Section& b, const std::string& value_key,
                                 const std::vector<std::string>& path, ParseContext& ctx);
void parse_output(Section& top, Case& c);
// grid.margin when not given: the largest displacement of any load over the run.
void set_automatic_margin(Case& c);
// On a graded grid, rectangular bodies fill whole cells: their edges must be grid lines.
void check_bodies_on_graded_grid(const Case& c);
// Once the grid is final: every body holds a particle, every cut-out removes one, and no two
// bodies share a particle position.
void check_body_seeding(const Case& c);
// A shape (input/parse_shape.cpp) from the table of a body or a cut-out (`what`: "body",
// "cut-out"), with the shape keys only.
Shape parse_shape(Section& s, const char* what);
// "[x0, y0]..[x1, y1]"
std::string describe_extent(const Box& b);

}  // namespace rupture
