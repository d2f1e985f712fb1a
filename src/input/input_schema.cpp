// rupture/input/input_schema.cpp
// The table of every input key (input/input_schema.hpp). Order matters: the keys of each table are
// listed in the order its parser's messages list them ("allowed here: ..."), and the tables in
// the order of the file's documentation. A range is written in the words of the validator's
// message for that key (test_input_schema checks a few), so a reader recognises one in the other.
#include "input/input_schema.hpp"

#include <fmt/format.h>

#include "input/law_registry.hpp"
#include "input/case.hpp"

namespace rupture {
namespace {

// The keys of a shape: a body's outline, or a cut-out (`prefix` "bodies.*" or
// "bodies.*.minus[]").
std::vector<KeyDoc> shape_keys(const std::string& prefix, bool cut_out) {
  const std::string p = prefix + ".";
  const std::string where = cut_out ? "must overlap the body" : "inside the grid";
  return {
      {p + "shape", "string", "", "\"rectangle\"",
       "\"rectangle\", \"polygon\", \"circle\", \"ellipse\"",
       "the kind of shape; only that kind's keys may be given", "\"circle\""},
      {p + "min", "[x, y]", "m", "required",
       cut_out ? "finite; anywhere (need not follow grid lines)"
               : "inside the grid; edges on grid lines (multiples of grid.cell_size from grid.min)",
       "lower-left corner of the rectangle", "[0.0, 0.0]", "shape = rectangle"},
      {p + "max", "[x, y]", "m", "required", "must exceed min in both components; " + where,
       "upper-right corner of the rectangle", "[0.04, 0.02]", "shape = rectangle"},
      {p + "vertices", "array of points", "m", "required",
       "at least 3 points; a simple polygon (edges meet only at shared vertices, no repeated "
       "vertex), nonzero area, either orientation; " +
           where,
       "the polygon's vertices [[x, y], ...]", "[[0.0, 0.0], [0.03, 0.0], [0.03, 0.01]]",
       "shape = polygon"},
      {p + "center", "[x, y]", "m", "required", "finite; the whole shape " + where,
       "centre of the circle or ellipse", "[0.02, 0.01]", "shape = circle | ellipse"},
      {p + "radius", "number", "m", "required", "> 0", "radius of the circle", "0.003",
       "shape = circle"},
      {p + "radii", "[a, b]", "m", "required", "both semi-axes [a, b] must be > 0",
       "semi-axes of the ellipse, a along its rotated x-axis", "[0.004, 0.0015]",
       "shape = ellipse"},
      {p + "angle", "number", "degrees", "0", "finite",
       "rotation of the ellipse's a-axis from +x, counter-clockwise", "30", "shape = ellipse"},
  };
}

// interface.*.law: the laws of the registry (input/law_registry.hpp) in its order, the first
// the default, with each law's note.
KeyDoc law_key() {
  std::string values, description = "traction-separation law";
  for (const LawEntry& e : law_registry()) {
    values += (values.empty() ? "\"" : ", \"") + e.name + "\"";
    if (!e.schema_note.empty()) description += "; " + e.schema_note;
  }
  return {"interface.*.law", "string", "", "\"" + law_registry().front().name + "\"", values,
          description, "\"bilinear\""};
}

// `function` and its keys (bc/time_function.hpp, docs/loads.md); `amplitude` is the
// [boundary] velocity key, which sits after `function` in its table.
std::vector<KeyDoc> time_function_keys(const std::string& prefix, bool boundary) {
  const std::string p = prefix + ".";
  const std::string value = boundary ? "velocity (m/s)" : "factor (dimensionless)";
  std::vector<KeyDoc> k = {
      {p + "function", "string", "", "\"constant\"",
       "\"constant\", \"trapezoid\", \"smooth_ramp\", \"ricker\", \"table\"",
       boundary ? "time function of the velocity: constant V1, the trapezoid impact pulse, a "
                  "smooth ramp, a Ricker wavelet or a table (docs/loads.md)"
                : "time function of the load's factor (value 1): constant, trapezoid, smooth "
                  "ramp, Ricker wavelet or table (docs/loads.md)",
       "\"trapezoid\""},
      {p + "rise_time", "number", "s", "required", "> 0", "rise time tr, from 0 to the full value",
       "0.1e-6", "function = trapezoid | smooth_ramp"},
      {p + "plateau_time", "number", "s", "required", ">= 0", "plateau time tp at the full value",
       "15e-6", "function = trapezoid"},
      {p + "fall_time", "number", "s", "required", "> 0", "fall time ts, back to 0", "1e-6",
       "function = trapezoid"},
      {p + "frequency", "number", "Hz", "required", "> 0, finite",
       "peak frequency f0 of the Ricker wavelet (1 - 2a) exp(-a), a = [pi f0 (t - t0)]^2; a "
       "warning when the grid has fewer than 8 cells per shortest S wavelength at 2.5 f0",
       "10.0", "function = ricker"},
      {p + "delay", "number", "s", "required", ">= 0, finite", "centre t0 of the Ricker wavelet",
       "0.15", "function = ricker"},
      {p + "table", "array of points", boundary ? "s, m/s" : "s, -",
       "required: table or table_file",
       "an array of [time, value] pairs of finite numbers: at least two points, times strictly "
       "increasing",
       "points [[t0, v0], [t1, v1], ...] of the " + value +
           ", linear between them, held before t0 and after the last",
       "[[0.0, 0.0], [1e-6, 1.0]]", "function = table"},
      {p + "table_file", "string", "", "required: table or table_file",
       "a readable CSV file of time,value lines (comma, semicolon or blank separated; optional "
       "header; # comments): at least two, times strictly increasing",
       "the table from a CSV file, relative to the case file's directory", "\"pulse.csv\"",
       "function = table"},
  };
  if (boundary)
    k.insert(k.begin() + 1, {p + "velocity", "number", "m/s", "required", "finite",
                             "amplitude V1 of the time function (the table holds the values "
                             "itself)",
                             "30.0", "function = constant | trapezoid | smooth_ramp | ricker"});
  return k;
}

std::vector<KeyDoc> build_schema() {
  std::vector<KeyDoc> s = {
      {"", "table", "", "", "", "A case file: the tables below, SI units throughout.", ""},
      {"title", "string", "", "\"\"", "any text",
       "name of the case, printed by rupture check and kept in run.json's input echo",
       "\"Rosakis 1999 intersonic shear crack\""},

      {"parameters", "table", "", "none", "numbers, each named by a letter or '_' then letters, digits, '_'",
       "Named numbers the case's values can be computed from: a string value beginning with '=' "
       "anywhere in the case (but the title) is an arithmetic expression of them (+ - * / ^, "
       "parentheses, pi, sqrt sin cos tan atan exp log abs), replaced by its value before the case "
       "is read (after --set, so `--set parameters.NAME=VALUE` moves every value that uses it). "
       "A whole result becomes an integer. Example: [parameters] offset = 0.5, and "
       "points = [[\"=0.128 - offset * 0.1016\", 0.0], ...].",
       ""},

      {"model", "table", "", "optional", "", "The 2D idealisation.", ""},
      {"model.plane", "string", "", "\"strain\"", "\"strain\", \"stress\"",
       "plane strain (eps_zz = 0, sigma_zz = nu (sxx + syy) kept) or plane stress (sigma_zz = 0)",
       "\"strain\""},

      {"materials", "named tables", "", "required", "at least one material, at most 255",
       "Isotropic linear elastic materials, one [materials.NAME] table each; bodies name them.",
       ""},
      {"materials.*", "table", "", "", "", "One material (docs/theory.md E1, E5).", ""},
      {"materials.*.youngs_modulus", "number", "Pa",
       "required, unless p_wave_speed and s_wave_speed are given", "> 0", "Young's modulus E",
       "5.2e9"},
      {"materials.*.poisson_ratio", "number", "",
       "required, unless p_wave_speed and s_wave_speed are given", "(-1, 0.5)",
       "Poisson's ratio nu", "0.34"},
      {"materials.*.p_wave_speed", "number", "m/s",
       "none (with s_wave_speed, instead of youngs_modulus and poisson_ratio)",
       "> 2/sqrt(3) s_wave_speed, finite",
       "P-wave speed c_P (3D; plane strain's c_D): lambda + 2 mu = rho c_P^2", "6000.0"},
      {"materials.*.s_wave_speed", "number", "m/s",
       "none (with p_wave_speed, instead of youngs_modulus and poisson_ratio)", "> 0, finite",
       "S-wave speed c_S: mu = rho c_S^2", "3464.0"},
      {"materials.*.density", "number", "kg/m^3", "required", "> 0", "mass density rho", "1246.0"},
      {"materials.*.kelvin_voigt", "number", "", "0", "[0, 1]",
       "Kelvin-Voigt damping eta / dt: sigma = C : (eps + eta eps_dot), eta this multiple of the "
       "time step (0.1 as SEM2DPACK and PyLith); enters the energy balance as viscous_dissipated "
       "and the step bound (docs/theory.md §16)",
       "0.1"},

      {"grid", "table", "", "required", "",
       "The background grid: a rectangular domain of square cells, optionally refined in nested "
       "boxes (docs/theory.md §5, README: Mesh refinement).",
       ""},
      {"grid.min", "[x, y]", "m", "required", "finite", "lower-left corner of the domain",
       "[0.0, -0.15]"},
      {"grid.max", "[x, y]", "m", "required", "must exceed grid.min in both components",
       "upper-right corner of the domain", "[0.125, 0.15]"},
      {"grid.cell_size", "number", "m", "required",
       "> 0; divides the domain extent into whole cells; at most 2e9 cells",
       "cell size; with refinement the finest cell size", "0.5e-3"},
      {"grid.particles_per_cell", "integer", "", "2", "[1, 8] (per direction)",
       "particles per cell along each direction (ppc x ppc per cell)", "2"},
      {"grid.coarse_cell_size", "number", "m", "0 (no refinement)",
       "0, or grid.cell_size times a power of two (1, 2, 4, ...)",
       "level-0 cell size of a refined grid: level L has cells of max(coarse_cell_size / 2^L, "
       "cell_size); 0 turns refinement off",
       "2e-3"},
      {"grid.refine", "named tables", "", "none", "needs grid.coarse_cell_size",
       "Refinement boxes, one [grid.refine.NAME] table each (ignored when coarse_cell_size = 0).",
       ""},
      {"grid.refine.*", "table", "", "", "",
       "One refinement box: cells of its level inside it; box edges on grid lines.", ""},
      {"grid.refine.*.min", "[x, y]", "m", "required",
       "box edges must lie on multiples of grid.cell_size from grid.min",
       "lower-left corner of the box", "[0.0, -0.06]"},
      {"grid.refine.*.max", "[x, y]", "m", "required",
       "must exceed min in both components; on multiples of grid.cell_size from grid.min",
       "upper-right corner of the box", "[0.09, 0.04]"},
      {"grid.refine.*.level", "integer", "", "required", "[1, 20]",
       "refinement level L: cells of coarse_cell_size / 2^L (no finer than grid.cell_size)", "1"},
      {"grid.refinement", "string", "", "depends: \"nested\" with grid.refine boxes, else \"graded\"",
       "\"graded\" or \"nested\" (needs grid.refine boxes)",
       "how refinement boxes are realized: nested levels with transition nodes, each level over "
       "its own box only (fewer particles, per-level time steps), or a graded tensor-product grid "
       "(fine rows and columns across the whole plate)",
       "\"graded\""},
      {"grid.margin", "number", "m",
       "depends: automatic, the largest prescribed or initial displacement of the run",
       "[0, half the larger domain extent]",
       "room outside the domain for free surfaces to move into, held by ghost cells", "1e-3"},

      {"bodies", "named tables", "", "required", "at least one body; bodies must not overlap",
       "The material bodies, one [bodies.NAME] table each (docs/geometry.md).", ""},
      {"bodies.*", "table", "", "", "",
       "One body: a shape of one material with a uniform initial velocity and stress, mapped to "
       "a velocity field; give `shape` and that shape's keys.",
       ""},
      {"bodies.*.material", "string", "", "required", "the name of a [materials] entry",
       "the body's material", "\"homalite\""},
      {"bodies.*.velocity", "[x, y]", "m/s", "[0, 0]", "finite", "initial velocity [vx, vy]",
       "[5.0, 0.0]"},
      {"bodies.*.stress", "[sxx, syy, sxy]", "Pa", "[0, 0, 0]", "an array of three finite numbers",
       "uniform initial stress; the strain follows from the plane mode's compliance",
       "[0.0, -1e6, 0.0]"},
      {"bodies.*.field", "string", "", "depends: the body's own name",
       "non-empty; at most 255 velocity fields",
       "velocity field: bodies sharing one are one continuum, bonded where they touch",
       "\"plate\""},
      {"bodies.*.minus", "array of tables", "", "none",
       "each must overlap the body and remove at least one particle",
       "Cut-outs (holes, notches): each [[bodies.NAME.minus]] table is one shape, with the "
       "shape keys of a body.",
       ""},
  };
  for (const std::vector<KeyDoc>& keys :
       {shape_keys("bodies.*.minus[]", true), shape_keys("bodies.*", false)})
    s.insert(s.end(), keys.begin(), keys.end());

  const std::vector<KeyDoc> time_solver = {
      {"time", "table", "", "required", "",
       "The run's length and time step (docs/theory.md E6, docs/time_step.md).", ""},
      {"time.end", "number", "s", "required", "> 0", "simulated time to run to", "19.2e-6"},
      {"time.cfl", "number", "", fmt::format("{:g}", TimeSpec{}.cfl), "(0, 1]",
       "Courant number: dt <= cfl h / c_D at the smallest cell", "0.4"},
      {"time.cohesive_safety", "number", "", fmt::format("{:g}", TimeSpec{}.cohesive_safety), "(0, 1]",
       "fraction of the cohesive interfaces' stability bound that dt may use", "0.9"},
      {"time.stop_at_interface_end", "boolean", "", "false", "true, false",
       "end the run once a crack tip comes within two cells of the end of its cohesive line",
       "true"},
      {"time.subcycling", "string", "",
       "depends: \"levels\" on nested levels where verified (solver.scheme = \"MUSL\", no [loads], no "
       "[absorbing], interfaces on one level, no growing crack), else \"none\"",
       "\"none\" or \"levels\" (needs grid.refinement = \"nested\" and solver.scheme = \"MUSL\"; "
       "not with [loads], [absorbing], interfaces on two levels or a growing crack)",
       "per-level time steps: each nested level steps at its own CFL step (2^k finest steps, "
       "docs/performance.md); the interface's level and finer ones every finest step", "\"none\""},

      {"solver", "table", "", "optional", "", "The MPM update and threads.", ""},
      {"solver.scheme", "string", "", "\"MUSL\"", "\"MUSL\", \"USL\", \"USF\"",
       "stress update last with a re-map (MUSL), last (USL) or first (USF)", "\"MUSL\""},
      {"solver.flip", "number", "", "1.0", "[0, 1] (1 = FLIP, 0 = PIC)",
       "FLIP/PIC blend of the particle velocity update", "1.0"},
      {"solver.mass", "string", "", "\"lumped\"",
       "\"lumped\", \"averaged\" (\"averaged\": one grid level, no [interface], no velocity region)",
       "the nodal mass of the grid equations: lumped, or the grid velocity projected with the "
       "consistent mass and the acceleration taken with the average of the lumped and consistent "
       "masses, which cancels the leading dispersion error (docs/theory.md §19; the step is "
       "1/sqrt(2) of the lumped one's)",
       "\"averaged\""},
      {"solver.threads", "integer", "", "0", "[0, 1024] (0 = all cores)",
       "OpenMP threads (results do not depend on it); 0: all cores, or 1 where another process "
       "holds a core and 1 thread steps faster (timed during the run: docs/performance.md)", "2"},
      {"solver.memory_limit_mib", "number", "MiB", "0 (the machine's memory)", ">= 0",
       "the largest memory estimate (rupture check's memory_estimate_mib) a run may start "
       "with; a case above it is refused before any allocation, and before its bodies' seed "
       "points are walked (counted from each drawn body's area: exactly for rectangles on grid "
       "lines, at least for other shapes). Raise it to run on purpose beyond the machine's "
       "memory (swap)", "65536"},

      {"absorbing", "table", "", "none", "",
       "Absorbing domain edges: viscous dashpots rho c_P (normal) and rho c_S (tangential) on "
       "the edge nodes, so waves leave the domain (docs/faults.md).",
       ""},
      {"absorbing.edges", "array of strings", "", "required",
       "each one of \"left\", \"right\", \"bottom\", \"top\", once; not an edge a [boundary] "
       "condition drives",
       "the absorbing edges", "[\"left\", \"right\", \"bottom\"]"},
      {"boundary", "named tables", "", "none", "",
       "Prescribed velocities on edges of the domain, one [boundary.NAME] table each (docs/theory.md E2).",
       ""},
      {"boundary.*", "table", "", "", "",
       "One velocity condition: a component on (part of) an edge, driven by a time function.", ""},
      {"boundary.*.edge", "string", "", "required", "\"left\", \"right\", \"bottom\", \"top\"",
       "the domain edge", "\"left\""},
      {"boundary.*.from", "number", "m", "depends: the start of the edge (grid.min along it)",
       "must lie on the edge: within grid.min..grid.max along it",
       "start of the driven stretch (y on left/right, x on bottom/top)", "-0.05"},
      {"boundary.*.to", "number", "m", "depends: the end of the edge (grid.max along it)",
       "must be >= from; on the edge", "end of the driven stretch", "0.0"},
      {"boundary.*.component", "string", "", "required", "\"x\", \"y\"",
       "the velocity component prescribed", "\"x\""},
      {"boundary.*.bodies", "array of strings", "", "all bodies", "names of [bodies] entries",
       "the bodies whose velocity fields the condition acts on", "[\"lower\"]"},
  };
  s.insert(s.end(), time_solver.begin(), time_solver.end());
  const std::vector<KeyDoc> bc_function = time_function_keys("boundary.*", true);
  s.insert(s.end(), bc_function.begin(), bc_function.end());
  s.push_back({"boundary.*.follow_edge", "boolean", "", "true",
               "true, false; only applies to the component normal to the edge",
               "drive the grid line at the edge's current position (initial + displacement) "
               "rather than the initial one",
               "true"});

  const std::vector<KeyDoc> loads = {
      {"loads", "named tables", "", "none", "",
       "Tractions on surface segments, body forces and prescribed velocities of material "
       "regions, one [loads.NAME] table each (docs/loads.md).",
       ""},
      {"loads.*", "table", "", "", "",
       "One load: `type` and that type's keys, times a dimensionless time function (value 1).", ""},
      {"loads.*.type", "string", "", "required",
       "\"traction\", \"body_force\", \"velocity\", \"point_force\"",
       "the kind of load; only that type's keys may be given", "\"traction\""},
      {"loads.*.from", "[x, y]", "m", "required", "must lie in the grid domain",
       "one end of the loaded surface segment", "[0.04, 0.0]", "type = traction"},
      {"loads.*.to", "[x, y]", "m", "required",
       "must lie in the grid domain; must differ from from", "the other end of the segment",
       "[0.04, 0.01]", "type = traction"},
      {"loads.*.traction", "[tx, ty]", "Pa", "required: traction, or normal and/or shear",
       "finite; not together with normal or shear", "traction in global axes", "[0.0, 5e6]",
       "type = traction"},
      {"loads.*.normal", "number", "Pa", "0", "finite; not together with traction",
       "traction along the outward normal of the material (> 0 tension)", "5e6", "type = traction"},
      {"loads.*.shear", "number", "Pa", "0", "finite; not together with traction",
       "traction along the segment, from -> to", "0.0", "type = traction"},
      {"loads.*.min", "[x, y]", "m", "required", "must lie in the grid domain",
       "lower-left corner of the box holding the driven material at t = 0", "[0.0, 0.0]",
       "type = velocity"},
      {"loads.*.max", "[x, y]", "m", "required",
       "must exceed min in both components; in the grid domain", "upper-right corner of the box",
       "[0.002, 0.01]", "type = velocity"},
      {"loads.*.direction", "[dx, dy]", "", "required", "must be a nonzero vector [dx, dy]",
       "direction d of the prescribed velocity (normalised; only the component along d is "
       "prescribed)",
       "[1.0, 0.0]", "type = velocity"},
      {"loads.*.velocity", "number", "m/s", "required", "finite",
       "speed along d, times the time function", "10.0", "type = velocity"},
      {"loads.*.acceleration", "[x, y]", "m/s^2", "required", "finite",
       "acceleration g of the body force m g", "[0.0, -9.81]", "type = body_force"},
      {"loads.*.point", "[x, y]", "m", "required",
       "must lie in the grid domain, inside a body's material (within one particle spacing of "
       "a particle of the bodies it names)",
       "where the point force acts (spread over the particles around it with their bilinear "
       "weights)",
       "[1500.0, -50.0]", "type = point_force"},
      {"loads.*.force", "[fx, fy]", "N/m", "required", "finite",
       "the line force F, times the time function (a Ricker wavelet: function = \"ricker\")",
       "[0.0, 1.0]", "type = point_force"},
      {"loads.*.bodies", "array of strings", "", "all bodies", "names of [bodies] entries",
       "the bodies loaded (traction: whose face, on a segment with material on both sides)",
       "[\"plate\"]", "type = traction | body_force | velocity | point_force"},
  };
  s.insert(s.end(), loads.begin(), loads.end());
  const std::vector<KeyDoc> load_function = time_function_keys("loads.*", false);
  s.insert(s.end(), load_function.begin(), load_function.end());

  const std::string horizontal = "the horizontal form (y, start, end)";
  const std::string cohesive = "law = xu_needleman | bilinear";
  const std::string friction = "law = slip_weakening";
  const std::string rate_state = "law = rate_state";
  const std::string faults = "law = slip_weakening | rate_state";
  const std::vector<KeyDoc> interfaces = {
      {"interface", "named tables", "", "none", "",
       "Cohesive interfaces, one [interface.NAME] table each, joining two bodies of different "
       "velocity fields, or lying inside one body, which is split along it (docs/theory.md §3, "
       "docs/interfaces.md, docs/cohesive_laws.md).",
       ""},
      {"interface.*", "table", "", "", "",
       "One interface: its line, given one way (horizontal: y, start, end; a polyline: points; "
       "a circle: center, radius), the bodies on either side (upper_body and lower_body) or the "
       "one body it lies in (body), its traction law and contact.",
       ""},
      {"interface.*.upper_body", "string", "", "required unless body is given",
       "a [bodies] entry (or a part of a split body), of another velocity field than "
       "lower_body; not with body",
       "the body on the side the line's normal (its direction turned +90 degrees) points to",
       "\"upper\""},
      {"interface.*.lower_body", "string", "", "required unless body is given",
       "a [bodies] entry; must differ from upper_body; not with body",
       "the body on the other side", "\"lower\""},
      {"interface.*.body", "string", "", "none (give upper_body and lower_body)",
       "a [bodies] entry holding the whole line (ends may lie on its edge); not with "
       "upper_body, lower_body, bonded_to, bonded_points",
       "the line lies inside this body, which is split along it: the part on the normal's side "
       "keeps the name, the other becomes NAME.below.IFACE (a closed line: its inside, "
       "NAME.inside.IFACE) with a field of its own; an end inside the body is extended "
       "straight to the body's edge and tied there",
       "\"plate\""},
      {"interface.*.y", "number", "m", "required in " + horizontal,
       "must be the bottom of the upper body and the top of the lower body (with body: inside "
       "it)",
       "height of a horizontal line (direction +x: the upper body lies above)", "0.0", horizontal},
      {"interface.*.start", "number", "m", "required in " + horizontal,
       "must lie where both bodies meet (with body: in the body or on its edge)",
       "left end of the horizontal line", "0.025", horizontal},
      {"interface.*.end", "number", "m", "required in " + horizontal,
       "must lie in (start, right end of where both bodies meet] (with body: > start, in the "
       "body or on its edge)",
       "right end of the horizontal line", "0.05", horizontal},
      {"interface.*.points", "array of points", "m", "required in the polyline form",
       "at least 2 points (3 when closed), in the grid, a simple line with the upper body on "
       "the side its normal points to (with body: inside that body)",
       "a polyline [[x, y], ...]; its normal is its direction turned +90 degrees",
       "[[0.01, 0.0], [0.03, 0.005]]", "the polyline form (points)"},
      {"interface.*.closed", "boolean", "", "false", "true, false",
       "close the polyline (its last point joins the first)", "true", "the polyline form (points)"},
      {"interface.*.center", "[x, y]", "m", "required in the circle form",
       "the circle in the grid, between the two bodies",
       "centre of a circular line; the upper body is the one inside", "[0.02, 0.01]",
       "the circle form (center, radius)"},
      {"interface.*.radius", "number", "m", "required in the circle form", "> 0",
       "radius of the circular line", "0.003", "the circle form (center, radius)"},
      {"interface.*.segments", "integer", "", "required",
       "an integer in [1, 1e8]; at least the number of pieces of the line; a circle needs at "
       "least 8",
       "number of cohesive segments along the line (4 Gauss points each)", "12000"},
      law_key(),
      {"interface.*.sigma_max", "number", "Pa", "required", "> 0", "normal (mode I) strength",
       "24e6", cohesive},
      {"interface.*.tau_max", "number", "Pa", "depends: sigma_max", "> 0",
       "tangential (mode II) strength", "24e6", cohesive},
      {"interface.*.delta_n", "number", "m", "required", "> 0",
       "normal characteristic opening (G_Ic = e sigma_max delta_n)", "0.4e-6",
       "law = xu_needleman"},
      {"interface.*.delta_t", "number", "m",
       "depends: from q, q e sigma_max delta_n / (sqrt(e/2) tau_max)", "> 0",
       "tangential characteristic opening (G_IIc = sqrt(e/2) tau_max delta_t)", "1.32e-6",
       "law = xu_needleman"},
      {"interface.*.q", "number", "", "1.0", "> 0", "q = phi_t / phi_n (docs/theory.md E7)", "1.0",
       "law = xu_needleman"},
      {"interface.*.r", "number", "", "0.0", ">= 0 and differ from 1",
       "Xu-Needleman coupling parameter r (docs/theory.md E7)", "0.0", "law = xu_needleman"},
      {"interface.*.penalty", "number", "", "1.0", ">= 0",
       "interpenetration penalty, a multiple of phi_n/delta_n^2 (xu_needleman) or of "
       "sigma_max/(lambda0 delta_nc) (bilinear)",
       "1.0", cohesive},
      {"interface.*.separation", "number", "", "5.0", "(0, 1000] (multiples of delta_t)",
       "a point separates once its jump reaches separation x delta_t", "5.0", "law = xu_needleman"},
      {"interface.*.delta_nc", "number", "m", "required", "> 0",
       "normal opening at zero traction (G_Ic = sigma_max delta_nc / 2)", "2e-6", "law = bilinear"},
      {"interface.*.delta_tc", "number", "m", "depends: delta_nc", "> 0",
       "tangential opening at zero traction (G_IIc = tau_max delta_tc / 2)", "2e-6",
       "law = bilinear"},
      {"interface.*.lambda0", "number", "", "0.01", "(0, 1)",
       "elastic fraction of the critical opening: the peak is at lambda0 delta_nc", "0.01",
       "law = bilinear"},
      {"interface.*.contact", "boolean", "", "depends: true with law = \"contact\", else false",
       "true, false; law = \"contact\" needs true",
       "contact with Coulomb friction where no cohesion is left (separated points, pre-cracks)",
       "true"},
      {"interface.*.friction", "number", "", "0.0", ">= 0", "Coulomb friction coefficient mu",
       "0.3", "contact = true"},
      {"interface.*.contact_stiffness", "number", "Pa/m",
       "depends: the law's penalty stiffness; with law = \"contact\" the P-wave modulus of the "
       "stiffer adjoining body over the cell size, M / h", "> 0",
       "normal contact penalty kn", "1e15", "contact = true"},
      {"interface.*.contact_tangential_stiffness", "number", "Pa/m", "0.0",
       ">= 0 (0 = contact_stiffness)", "tangential stick stiffness kt", "1e15", "contact = true"},
      {"interface.*.static_friction", "number", "", "required", ">= 0",
       "static friction coefficient mu_s (strength = cohesion + mu x compression)", "0.677",
       friction},
      {"interface.*.dynamic_friction", "number", "", "required", "[0, static_friction]",
       "dynamic friction coefficient mu_d, reached after a slip of dc", "0.525", friction},
      {"interface.*.dc", "number", "m", "required", "> 0",
       "Dc: the slip-weakening distance (slip_weakening), the state evolution slip (rate_state)",
       "0.4", faults},
      {"interface.*.cohesion", "number", "Pa", "0.0", ">= 0", "cohesion added to the strength",
       "0.0", friction},
      {"interface.*.initial_traction", "[normal, shear]", "Pa",
       "[0.0, 0.0] (required with law = rate_state)",
       "finite (rate_state: normal < 0, shear != 0, balanced by a finite state)",
       "initial fault traction (traction-offset form): normal (tension positive, < 0 "
       "compresses) and shear (> 0 drives the upper body along the tangent, +x on a line drawn "
       "in +x)",
       "[-120e6, 70e6]", faults},
      {"interface.*.normal_stiffness", "number", "Pa/m",
       "depends: M / h, the stiffer body's P-wave modulus over the cell size", "> 0",
       "penalty against interpenetration kn", "1e9", faults},
      {"interface.*.stick_stiffness", "number", "Pa/m", "depends: M / h, as normal_stiffness",
       "> 0", "tangential spring kt of stuck faces (rate_state: of the faces, whose slip rate is "
       "solved against it)",
       "1e9", faults},
      {"interface.*.normal_relaxation", "string", "", "\"none\"", "none, time, slip",
       "the normal stress friction sees, regularized after Prakash & Clifton (1993) for faults "
       "between different materials: none (the actual compression; scales given stay "
       "unused), time (d sigma*/dt = -(sigma* - sigma)/T), slip (d sigma*/dt = -(|V| + V*)/L "
       "(sigma* - sigma)); docs/faults.md",
       "\"none\"", faults},
      {"interface.*.normal_relaxation_time", "number", "s", "required with normal_relaxation = time",
       "> 0", "T of the time form", "0.01", faults},
      {"interface.*.normal_relaxation_slip", "number", "m", "required with normal_relaxation = slip",
       "> 0", "L of the slip form", "0.2", faults},
      {"interface.*.normal_relaxation_rate", "number", "m/s",
       "required with normal_relaxation = slip", ">= 0", "V* of the slip form (relaxation where "
       "the fault does not slip)", "1.0", faults},
      {"interface.*.evolution", "string", "", "\"aging\"", "aging, slip, flash_heating",
       "the state evolution law: aging (d theta/dt = 1 - V theta/Dc), slip (d psi/dt = -(V/Dc) "
       "(psi - psi_ss)), flash_heating (the slip law with strong rate weakening, TPV103)",
       "\"aging\"", rate_state},
      {"interface.*.a", "number", "", "required", "> 0",
       "direct effect a of f = a asinh[V/(2 V0) exp(psi/a)]", "0.008", rate_state},
      {"interface.*.b", "number", "", "required", "> 0", "evolution effect b", "0.012", rate_state},
      {"interface.*.reference_slip_rate", "number", "m/s", "1e-6", "> 0", "reference slip rate V0",
       "1e-6", rate_state},
      {"interface.*.reference_friction", "number", "", "0.6", ">= 0",
       "steady-state friction f0 at V0", "0.6", rate_state},
      {"interface.*.weakened_friction", "number", "", "required with evolution = flash_heating",
       ">= 0", "fully weakened friction f_w", "0.2", rate_state},
      {"interface.*.weakening_slip_rate", "number", "m/s",
       "required with evolution = flash_heating", "> 0", "weakening slip rate V_w", "0.1",
       rate_state},
      {"interface.*.initial_slip_rate", "number", "m/s", "required", "> 0",
       "initial slip rate V_ini: the initial state balances initial_traction at it, psi = a "
       "ln[(2 V0/V_ini) sinh(|shear|/(a x compression))]",
       "1e-12", rate_state},
      {"interface.*.nucleation_stress", "number", "Pa", "0.0", "finite",
       "nucleation shear stress dtau added to the prestress as dtau F(r) G(t)", "25e6",
       rate_state},
      {"interface.*.nucleation_centre", "[x, y]", "m", "[0.0, 0.0]", "finite; with nucleation_stress",
       "centre of the nucleation stress (r is the distance from it)", "[0.0, 0.0]", rate_state},
      {"interface.*.nucleation_radius", "number", "m", "0.0", ">= 0; with nucleation_stress",
       "R of F(r) = exp(r^2/(r^2 - R^2)) for r < R, else 0 (0: F = 1 on the whole fault)",
       "3000.0", rate_state},
      {"interface.*.taper", "table", "", "none", "",
       "the smooth taper of TPV101-103: within half_width of centre the fault's a, b, dc, "
       "weakening_slip_rate; beyond half_width + width this table's; between, B(r) = 0.5 [1 + "
       "tanh(w/(r - W - w) + w/(r - W))] blends them (docs/faults.md)",
       "", rate_state},
      {"interface.*.taper.centre", "[x, y]", "m", "required", "finite",
       "the point r is measured from (the hypocentre)", "[0.0, 0.0]"},
      {"interface.*.taper.half_width", "number", "m", "required", ">= 0",
       "W: the untapered distance from the centre", "15000.0"},
      {"interface.*.taper.width", "number", "m", "required", "> 0", "w: the taper's width",
       "3000.0"},
      {"interface.*.taper.a", "number", "", "not tapered", "> 0", "a beyond W + w", "0.016"},
      {"interface.*.taper.b", "number", "", "not tapered", "> 0", "b beyond W + w", "0.012"},
      {"interface.*.taper.dc", "number", "m", "not tapered", "> 0", "Dc beyond W + w", "0.02"},
      {"interface.*.taper.weakening_slip_rate", "number", "m/s", "not tapered",
       "> 0; with evolution = flash_heating", "V_w beyond W + w", "1.0"},
      {"interface.*.profile", "table", "", "none", "",
       "rate_state parameters tabulated along the fault, each [[coordinate, value], ...] "
       "piecewise linear in `along` and constant beyond its ends, resolved once per Gauss point "
       "(docs/faults.md)",
       "", rate_state},
      {"interface.*.profile.along", "string", "", "required", "x, y, s",
       "the coordinate of the tables: the reference position's x or y, or s, the arc length "
       "from the line's start (m)",
       "\"x\""},
      {"interface.*.profile.a", "array of [coordinate, value]", "", "not tabulated",
       "at least two points, coordinates increasing, values > 0", "a along the fault",
       "[[-18000.0, 0.008], [18000.0, 0.008]]"},
      {"interface.*.profile.b", "array of [coordinate, value]", "", "not tabulated",
       "at least two points, coordinates increasing, values > 0", "b along the fault",
       "[[-18000.0, 0.012], [18000.0, 0.012]]"},
      {"interface.*.profile.dc", "array of [coordinate, value]", "m", "not tabulated",
       "at least two points, coordinates increasing, values > 0", "Dc along the fault",
       "[[-18000.0, 0.02], [18000.0, 0.02]]"},
      {"interface.*.profile.weakening_slip_rate", "array of [coordinate, value]", "m/s",
       "not tabulated", "as a; with evolution = flash_heating", "V_w along the fault",
       "[[-18000.0, 0.1], [18000.0, 0.1]]"},
      {"interface.*.nucleation_time", "number", "s", "0.0", ">= 0; with nucleation_stress",
       "T of G(t) = exp((t - T)^2/(t (t - 2T))) for t < T, else 1 (0: a step at t = 0+)", "1.0",
       rate_state},
      {"interface.*.overstressed", "boolean", "", "false", "true, false",
       "allow an initial shear traction above the static strength on the whole fault (it all "
       "slides at once, as in the 1D slip-weakening test); without it that is an input error",
       "true", friction},
      {"interface.*.stress_intensity", "boolean", "", "false", "true, false",
       "record J, K_I and K_II at the crack's tips over time (stress_intensity_NAME.csv; "
       "docs/fracture.md): the line's ends that meet a bonded stretch on a pre-crack, the "
       "running tip otherwise",
       "true"},
      {"interface.*.j_domains", "array of numbers", "cells", "[4.0, 6.0, 8.0]",
       "1 to 8, increasing, each >= 2; with stress_intensity = true or growth",
       "the J domains' outer radii (circles about the tip; inner radius: "
       "half of each)",
       "[4.0, 6.0, 8.0]"},
      {"interface.*.growth", "string", "", "none", "none, max_hoop, energy, cohesive, prescribed",
       "the crack's tips grow by this criterion (docs/fracture.md, \"Growth\"): max_hoop, when "
       "the hoop stress intensity in the maximum hoop stress direction reaches toughness "
       "(Erdogan-Sih); energy, when G = (K_I^2 + K_II^2) / E' reaches fracture_energy; "
       "cohesive (law = bilinear), when the last segment is past the law's peak traction, or a "
       "cut's tip is pulled open; prescribed, at growth_speed from growth_start (a generation-"
       "phase run: the motion given, K read); a "
       "crack (law = \"contact\", or a cohesive law that its new segments carry) drawn inside "
       "one body (body = ...), on a uniform grid or nested levels (one step for all; the path "
       "inside the level that holds the crack), on one process or several; records K at the tips "
       "(stress_intensity)",
       "\"max_hoop\""},
      {"interface.*.toughness", "number", "Pa m^1/2", "none", "> 0; with growth = max_hoop",
       "K_Ic, the mode-I fracture toughness", "1.0e6"},
      {"interface.*.fracture_energy", "number", "J/m^2", "none", "> 0; with growth = energy",
       "G_c, the critical energy release rate", "200.0"},
      {"interface.*.plane_fracture_energy", "number", "J/m^2", "none",
       "> 0; with growth = energy and growth_direction = max_hoop",
       "G_c of a weak plane: the drawn line's straight extension beyond each tip. A tip still on "
       "it grows along it when (K_I+^2 + K_II^2) / E' reaches this, or kinks out at the maximum "
       "hoop stress angle when the kinked crack's G reaches fracture_energy, whichever ratio is "
       "larger (He & Hutchinson; docs/fracture.md, \"A weak plane ahead\")",
       "26.1"},
      {"interface.*.growth_direction", "string", "", "max_hoop", "max_hoop, straight; with growth",
       "the direction of a new segment: the maximum hoop stress direction from K_I, K_II, or "
       "straight on along the crack", "\"max_hoop\""},
      {"interface.*.growth_speed", "number", "m/s", "none", "> 0; with growth = prescribed (below 0.95 c_R with running_tip)",
       "the tips' speed: a tip grows a segment whenever its grown path plus the segment is within "
       "growth_speed (t - growth_start)", "300.0"},
      {"interface.*.growth_start", "number", "s", "0", ">= 0; with growth = prescribed",
       "when the tips start to run", "1.0e-6"},
      {"interface.*.running_tip", "boolean", "", "false",
       "true, false; with growth (not with plane_fracture_energy)",
       "read a growing tip as running at its speed (over the outer J domain's radius of path): K_I, "
       "K_II from the interaction integral in its steady form with the running tip's fields "
       "(Freund 1990, sec. 4.3), and the energy criterion's G = (A_I K_I^2 + A_II K_II^2) / E' "
       "(docs/fracture.md, \"A running tip\"); false: the stationary forms at every speed",
       "true"},
      {"interface.*.growth_step", "number", "cells", "0.5", "(0, 0.5]; with growth",
       "the length of one new segment (a tip grows at most one segment per step)", "0.5"},
      {"interface.*.branching", "string", "", "none", "none, yoffe; with growth = energy or max_hoop",
       "when a growing tip splits in two: yoffe, once the tip's speed (over the outer J domain's "
       "radius of path) reaches the speed where the running mode-I field's largest hoop stress "
       "leaves the crack's axis (Yoffe 1951; Freund 1990), the two new tips leaving at the angles "
       "of that maximum (docs/fracture.md, \"Branching\")",
       "\"yoffe\""},
      {"interface.*.max_branches", "integer", "", "1", "1 to 8; with branching",
       "how many times the crack's tips may split (each split keeps a velocity field, NAME.branchK, "
       "for the wedge between its two tips)", "1"},
      {"interface.*.nucleation", "string", "", "\"none\"", "\"none\", \"strength\"; with growth",
       "strength: the drawn line is intact material (tied, as its extension) until the mean normal "
       "stress across one of its segments, over the particles within a cell of it, reaches "
       "nucleation_strength; then it is the crack drawn, and grows (docs/fracture.md, \"Nucleation "
       "at a drawn site\")",
       "\"strength\""},
      {"interface.*.nucleation_strength", "number", "Pa", "the law's sigma_max",
       "> 0; with nucleation = \"strength\" (required with law = contact)",
       "the normal stress across the drawn line at which it comes loose", "10.45e6"},
      {"interface.*.drawn_open", "boolean", "", "false", "true, false; with law = xu_needleman or bilinear",
       "the drawn line is a cut (its points start separated, as a pre-crack's) and the segments a "
       "growing crack adds carry the law", "true"},
      {"interface.*.rupture_slip_rate", "number", "m/s", "0.001", "> 0",
       "a node's rupture time is the first time its slip rate exceeds this "
       "(interface_nodes.csv)",
       "0.001"},
      {"interface.*.stretches", "array of tables", "", "none", "",
       "stretches of the fault with their own parameters (a nucleation patch, a stress patch, a "
       "barrier): each [[interface.NAME.stretches]] has from, to and any of static_friction, "
       "dynamic_friction, dc, cohesion, initial_traction, normal_stiffness, stick_stiffness "
       "(rate_state: a, b, dc, reference_friction, weakened_friction, weakening_slip_rate, "
       "initial_traction, normal_stiffness, stick_stiffness); later stretches override earlier "
       "ones",
       "", faults},
      {"interface.*.stretches[].from", "[x, y]", "m", "required",
       "on the interface's line (within half a cell)", "one end of the stretch",
       "[-1500.0, 0.0]"},
      {"interface.*.stretches[].to", "[x, y]", "m", "required",
       "on the interface's line; differs from from", "the other end", "[1500.0, 0.0]"},
      {"interface.*.stretches[].static_friction", "number", "", "the interface's", ">= 0",
       "mu_s here (a barrier: a very high value)", "10000.0"},
      {"interface.*.stretches[].dynamic_friction", "number", "", "the interface's",
       "[0, static_friction]", "mu_d here", "0.525"},
      {"interface.*.stretches[].dc", "number", "m", "the interface's", "> 0", "Dc here", "0.4"},
      {"interface.*.stretches[].a", "number", "", "the interface's", "> 0",
       "rate_state: a here (a velocity-strengthening barrier: a > b)", "0.016"},
      {"interface.*.stretches[].b", "number", "", "the interface's", "> 0", "rate_state: b here",
       "0.012"},
      {"interface.*.stretches[].reference_friction", "number", "", "the interface's", ">= 0",
       "rate_state: f0 here", "0.6"},
      {"interface.*.stretches[].weakened_friction", "number", "", "the interface's", ">= 0",
       "rate_state: f_w here", "0.2"},
      {"interface.*.stretches[].weakening_slip_rate", "number", "m/s", "the interface's", "> 0",
       "rate_state: V_w here", "0.1"},
      {"interface.*.stretches[].cohesion", "number", "Pa", "the interface's", ">= 0",
       "cohesion here", "0.0"},
      {"interface.*.stretches[].initial_traction", "[normal, shear]", "Pa", "the interface's",
       "finite", "initial traction here (a nucleation patch: shear above the static strength)",
       "[-120e6, 81.6e6]"},
      {"interface.*.stretches[].normal_stiffness", "number", "Pa/m", "the interface's", "> 0",
       "kn here", "1e9"},
      {"interface.*.stretches[].stick_stiffness", "number", "Pa/m", "the interface's", "> 0",
       "kt here", "1e9"},
      {"interface.*.bonded_to", "number", "m", "none",
       "must lie in (end, right end of where both bodies meet]",
       "tie the two halves from end to here (a bonded stretch ahead of the weak plane)", "0.125",
       horizontal},
      {"interface.*.bonded_points", "array of points", "m", "none",
       "at least 2 points, in the grid, a simple line between the two bodies",
       "a tied (bonded) stretch along these points", "[[0.03, 0.005], [0.05, 0.005]]",
       "the polyline or circle form"},

      {"stations", "named tables", "", "none", "",
       "Points whose time series the run records, one [stations.NAME] table each "
       "(stations/NAME.csv; docs/faults.md).",
       ""},
      {"stations.*", "table", "", "", "",
       "One station: on a fault (interface given: slip, slip rate, opening, shear and normal "
       "traction, jump rate) or in a body (the position, velocity and displacement of the "
       "particle nearest the point).",
       ""},
      {"stations.*.at", "[x, y]", "m", "required",
       "in the grid; with interface: on that interface's line (within half a cell)",
       "where the station is", "[4500.0, 0.0]"},
      {"stations.*.interface", "string", "", "none (a body station)", "an [interface] entry",
       "the fault the station lies on", "\"fault\""},
      {"stations.*.read", "string", "", "\"nearest\"", "\"nearest\", \"interpolated\" (body stations)",
       "a body station's reading: the particle nearest the point at t = 0, or a linear "
       "least-squares fit of its body's particles within a cell of the point, evaluated at the "
       "point (second order; extrapolates to a free surface on the point)",
       "\"interpolated\""},

      {"output", "table", "", "optional", "", "What the run writes, and how often.", ""},
      {"output.history_interval", "number", "s", "depends: time.end / 200",
       ">= 0 (s; 0 = every step)", "energy history (history.csv) interval", "0.1e-6"},
      {"output.snapshot_interval", "number", "s", "0", ">= 0 (s; 0 = no snapshots)",
       "particle snapshots (snapshots/*.h5, particles.xdmf) interval", "2.2e-6"},
      {"output.progress_interval", "number", "s", "1.0", "> 0 (wall-clock s)",
       "progress line interval, in wall-clock seconds", "1.0"},
      {"output.station_interval", "number", "s", "0", ">= 0 (s; 0 = every step)",
       "station samples (stations/*.csv) interval", "0.005"},
      {"output.crack_sample_interval", "number", "s", "depends: max(0.05e-6, time.end / 384)", "> 0",
       "crack-tip sampling interval (docs/theory.md E10); speeds use 31 samples (E11)", "0.02e-6"},
      {"output.interface_interval", "number", "s", "depends: output.snapshot_interval",
       ">= 0 (s; 0 = none)", "interface profiles (interface/interface_*.csv) interval", "0.2e-6"},
      {"output.mach_interval", "number", "s", "depends: output.snapshot_interval",
       ">= 0 (s; 0 = none)",
       "shear Mach-angle readings behind intersonic tips (docs/theory.md E12; mach_angle.csv) interval",
       "1e-6"},
      {"output.snapshot_region_min", "[x, y]", "m", "none (the whole domain)",
       "given together with snapshot_region_max",
       "lower-left corner of the region whose particles snapshots hold", "[0.0, -0.04]"},
      {"output.snapshot_region_max", "[x, y]", "m", "none (the whole domain)",
       "must exceed output.snapshot_region_min in both components",
       "upper-right corner of that region", "[0.075, 0.04]"},
  };
  s.insert(s.end(), interfaces.begin(), interfaces.end());
  return s;
}

}  // namespace

const std::vector<KeyDoc>& input_schema() {
  static const std::vector<KeyDoc> schema = build_schema();
  return schema;
}

}  // namespace rupture
