// rupture/io/case_parse.hpp
// One parse function per table of the input file (io/case_toml builds the Case by calling them
// in order). Each validates its table completely; cross-table rules that need several tables
// live in io/case_checks. Internal to io/.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "io/case.hpp"
#include "io/toml_section.hpp"

namespace rupture {

// Names already parsed, for the tables that refer to them.
struct ParseContext {
  std::map<std::string, int> material_index;
  std::map<std::string, int> body_index;  // index into Case::bodies
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
void parse_interfaces(Section& top, Case& c, ParseContext& ctx);
void parse_loads(Section& top, Case& c, ParseContext& ctx);
// `function` and its keys (io/parse_time_function.cpp). value_key names the amplitude key
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
// A shape (io/parse_shape.cpp) from the table of a body or a cut-out (`what`: "body",
// "cut-out"), with the shape keys only.
Shape parse_shape(Section& s, const char* what);
// "[x0, y0]..[x1, y1]"
std::string describe_extent(const Box& b);

}  // namespace rupture
