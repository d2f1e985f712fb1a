// rupture/input/case.hpp
// A validated simulation case: everything the solver needs, in SI units, produced only by
// input/case_toml (which owns all input validation). Plain data; no behaviour.
#pragma once
#include <algorithm>
#include <string>
#include <vector>

#include "bc/loads.hpp"
#include "bc/velocity_bc.hpp"
#include "cohesive/interface.hpp"
#include "geometry/shape.hpp"
#include "grid/grid.hpp"
#include "material/elastic.hpp"

namespace rupture {

enum class Scheme { USF, USL, MUSL };
// The nodal mass the grid equations use (solver.mass; solver/consistent_mass.hpp).
enum class MassMatrix { lumped, averaged };

// A body: a region of one material with a uniform initial velocity and stress, mapped to one
// velocity field. Bodies that share a field are one continuum (one set of grid arrays).
struct BodySpec {
  std::string name;
  int material = 0;             // index into Case::materials
  Region region;                // shape and cut-outs (geometry/shape.hpp), m; a body split along
                                // an interface's line keeps its side of it (region.sides)
  double min[2]{}, max[2]{};    // bounding box of the outer shape (a rectangle: itself), m
  double velocity[2]{};         // initial velocity, m/s
  double stress[3]{};           // initial uniform stress sxx, syy, sxy, Pa (sigma_zz follows
                                // from the plane mode; the strain from the compliance)
  int field = 0;                // velocity field: index into Case::field_names

  // An axis-aligned rectangle on grid lines without cut-outs, not split by a line: seeded as
  // always (bitwise).
  bool plain_rectangle() const {
    return region.outer.kind == ShapeKind::rectangle && region.minus.empty() &&
           region.sides.empty();
  }
};

// Mesh refinement (theory §5) as nested boxes with a level each, level 0 being the whole plate
// at coarse_cell_size and each level halving the size: level L has cells of
// max(coarse_cell_size / 2^L, cell_size). cell_size is the finest size, so changing it alone
// adds or drops the deepest levels.
struct RefineLevel {
  std::string name;
  double min[2]{}, max[2]{};  // m
  int level = 1;
};

struct GridSpec {
  double min[2]{}, max[2]{};     // physical domain, m
  double cell_size = 0.0;        // h: the uniform cell size, or the finest one when refined, m
  double coarse_cell_size = 0.0; // level-0 size when refined (0: uniform grid), m
  std::vector<RefineLevel> refine;
  int particles_per_cell = 2;    // per direction (2 -> 2x2, theory §2), on every level
  // Width of the empty band of ghost cells around the domain that free surfaces may bulge
  // into, beyond the two ghost cells every grid has, m. Unless given (grid.margin), the largest
  // displacement over the run of any prescribed velocity or body velocity: a surface driven
  // by those moves by about as much (the reference problem's crop bottom moved 0.2 mm while
  // its driven edge moved 0.45 mm, more than two 0.125 mm ghost cells hold).
  double margin = 0.0;
  // How a refined grid is realized (theory §5): nested levels with transition nodes
  // (grid/nested.hpp, solver/nested_state.hpp; the default with [grid.refine] boxes), or a
  // graded tensor-product grid (grid/grid.hpp; grid.refinement = "graded").
  bool nested = false;

  bool refined() const { return coarse_cell_size > 0.0; }
  double max_margin() const { return 0.5 * std::max(max[0] - min[0], max[1] - min[1]); }  // m
  double level_size(int level) const {  // m
    return std::max(coarse_cell_size / double(1L << level), cell_size);
  }
};

// Per-level time steps on nested levels (solver/nested_subcycle.cpp): none (one dt for every
// level) or levels (each level at its own CFL step). Unless time.subcycling is given, levels
// where it is verified (input/case_toml.cpp:
// set_default_subcycling), none elsewhere.
enum class Subcycling { none, levels };

struct TimeSpec {
  double end = 0.0;  // s
  double cfl = 0.4;  // Delta t = cfl * h / c_D (theory E6)
  // Delta t <= cohesive_safety * 2 / sqrt(lambda_bulk + lambda_cohesive), the bound of the
  // discrete system recomputed every step (solver/time_step.hpp, docs/time_step.md); any value
  // in (0, 1] is stable by construction, 1 sits on the bound.
  double cohesive_safety = 0.9;
  // End the run early once the crack tip of any interface reaches the end of its cohesive line
  // (see CrackSummary::end_reached_time): a crack running into the bonded part stops there, and
  // the sustained speed (last 4 us of the run) would then measure the arrest, not the crack.
  bool stop_at_interface_end = false;
  Subcycling subcycling = Subcycling::none;
  bool subcycling_given = false;  // time.subcycling was in the input (not the default)
};

struct SolverSpec {
  Scheme scheme = Scheme::MUSL;
  double flip = 1.0;  // FLIP fraction of the particle velocity update (1 = FLIP, 0 = PIC)
  MassMatrix mass = MassMatrix::lumped;
  int threads = 0;    // 0 = OpenMP default
  double memory_limit_mib = 0.0;  // largest memory estimate a run may start with (0 = RAM)
};

struct OutputSpec {
  double history_interval = 0.0;   // s; 0 = every step
  double snapshot_interval = 0.0;  // s; 0 = no snapshots
  double progress_interval = 1.0;  // wall-clock seconds between progress lines
  double crack_sample_interval = 0.05e-6;  // crack-tip sampling interval, s (E10)
  double interface_interval = 0.0;  // interface profiles (DIR/interface/*.csv), s; 0 = none
  double mach_interval = 0.0;       // shear Mach-angle readings (DIR/mach_angle*.csv), s; 0 = none
  double station_interval = 0.0;    // station samples (DIR/stations/*.csv), s; 0 = every step
  bool has_snapshot_region = false;
  double snapshot_region[4]{};      // xmin, ymin, xmax, ymax of the particles written, m
};

// A station of [stations]: a named point whose time series the run records
// (output/stations.hpp records it).
struct StationSpec {
  std::string name;
  double x = 0.0, y = 0.0;  // m
  int interface = -1;       // index into Case::interfaces; -1: a body station
  // A body station's reading (stations.NAME.read): the nearest particle's (false), or a linear
  // least-squares fit of the particles within a cell of the point, evaluated at the point (true).
  bool interpolated = false;
};

struct Case {
  std::string title;
  PlaneMode plane = PlaneMode::strain;
  std::vector<ElasticMaterial> materials;
  std::vector<BodySpec> bodies;
  // Velocity fields (theory §3), numbered in order of first appearance among the bodies
  // (bodies.NAME.field, by default the body's own name). At most 255.
  std::vector<std::string> field_names;
  GridSpec grid;
  TimeSpec time;
  SolverSpec solver;
  std::vector<VelocityBC> boundary;
  std::vector<Edge> absorbing_edges;  // [absorbing].edges: viscous dashpots (bc/absorbing.hpp)
  Loads loads;  // [loads]: tractions, body forces, velocity regions (bc/loads.hpp)
  std::vector<InterfaceSpec> interfaces;  // cohesive interfaces (theory §3)
  std::vector<std::string> interface_names;
  std::vector<StationSpec> stations;  // [stations] (output/stations.hpp)
  OutputSpec output;
  std::string input_toml;  // the merged input (file + --set) as TOML, echoed into run.json
  bool read_table_files = false;  // some time function came from a table_file (inline above)
  std::vector<std::string> warnings;  // legal but suspicious input (input/case_checks), for stderr
};

const char* scheme_name(Scheme s);

// Whether the point (x, y) (m) lies in the body's region (geometry/shape.hpp).
inline bool body_contains(const BodySpec& b, double x, double y) { return contains(b.region, x, y); }

// The background grid a case asks for: uniform, or graded from its refinement levels.
Grid build_grid(const GridSpec& g);
// The refinement boxes of g with their cell sizes (for make_graded_grid and make_nested_grid).
std::vector<RefineBox> refine_boxes(const GridSpec& g);

}  // namespace rupture
