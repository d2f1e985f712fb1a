// rupture/solver/crack_junction.cpp
#include "solver/crack_junction.hpp"

#include <algorithm>
#include <optional>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "solver/crack_cut.hpp"

namespace rupture {

std::vector<OtherLine> other_lines(const Case& c, const RunState& s, const std::vector<CrackGrowthRecord>& records,
                                   std::size_t k, const std::vector<std::size_t>& own) {
  const int level = s.interface_levels[k];
  const State& L = s.levels[std::size_t(level)];
  std::vector<OtherLine> lines;
  for (std::size_t slot = 0; slot < L.interfaces.size(); ++slot) {
    if (std::find(own.begin(), own.end(), slot) != own.end()) continue;
    const InterfaceSpec& spec = L.interfaces[slot].spec;
    std::string name = "a line";
    for (std::size_t j = 0; j < c.interfaces.size() && j < s.interface_slots.size(); ++j) {
      if (s.interface_levels[j] == level && s.interface_slots[j] == slot)
        name = fmt::format("interface '{}'", c.interface_names[j]);
      if (j < records.size())
        for (const std::size_t b : records[j].branch_slots)
          if (b == slot) name = fmt::format("a branch of interface '{}'", c.interface_names[j]);
    }
    const bool in_body = drawn_in_crack_body(c, k, spec);
    lines.push_back({spec.geometry(), name, false, in_body});
    for (const Polyline& t : spec.tie_geometries()) lines.push_back({t, name, true, in_body});
  }
  return lines;
}

namespace {

std::string body_of(const Case& c, std::size_t k) {
  return c.bodies[std::size_t(c.interfaces[k].upper_body)].name;
}

}  // namespace

void stop_at_segment_junction(const Case& c, std::size_t k, double time, const std::vector<OtherLine>& others,
                              const Point& from, const Point& to, double h) {
  for (const OtherLine& o : others) {
    const std::optional<LineMeeting> m = segment_meets_line(o.line, from, to, h);
    if (!m) continue;
    const std::string what =
        o.in_body ? fmt::format("a junction of two lines drawn inside one body ({}) is not supported yet (each crack "
                                "splits the body into two velocity fields along itself and its tied extension; the "
                                "pieces a junction cuts off would need fields of their own",
                                body_of(c, k))
                  : fmt::format("a crack that reaches an interface between two bodies (a T-junction on the edge of "
                                "{}) is not supported yet (that interface's face would lie on the two velocity "
                                "fields on either side of the crack",
                                body_of(c, k));
    throw SimulationError(fmt::format(
        "crack growth: interface '{}' has its tip at ({:.6g}, {:.6g}) m at t = {:.6g} s, and its next "
        "segment, to ({:.6g}, {:.6g}) m, comes within {:.3g} m (one cell) of {}'s {} at ({:.6g}, {:.6g}) m: "
        "{}: docs/fracture.md, \"Junctions\"); the run stops here, with what it wrote. Draw the lines "
        "farther apart{}",
        c.interface_names[k], from.x, from.y, time, to.x, to.y, h, o.name,
        o.tie ? "tied extension (intact material, where it holds its two fields together)" : "line", m->at.x,
        m->at.y, what, o.in_body ? ", or in separate bodies joined by an [interface]" : ""));
  }
}

void stop_at_tie_junction(const Case& c, std::size_t k, double time, const std::vector<OtherLine>& others,
                          const std::vector<Polyline>& ties, double h) {
  for (const Polyline& tie : ties)
    for (std::size_t i = 0; i + 1 < tie.num_vertices(); ++i)
      for (const OtherLine& o : others) {
        const std::optional<LineMeeting> m =
            segment_meets_line(o.line, {tie.x[i], tie.y[i]}, {tie.x[i + 1], tie.y[i + 1]}, 1e-6 * h);
        if (!m) continue;
        throw SimulationError(fmt::format(
            "crack growth: interface '{}' turned at t = {:.6g} s so that its tied extension (from "
            "({:.6g}, {:.6g}) m to ({:.6g}, {:.6g}) m, the straight way on to the edge of {}) meets {}'s {} at "
            "({:.6g}, {:.6g}) m: {} is not supported yet (that interface's face would lie on two velocity "
            "fields, those on either side of the crack: docs/fracture.md, \"Junctions\"); the run stops "
            "here, with what it wrote",
            c.interface_names[k], time, tie.x[i], tie.y[i], tie.x[i + 1], tie.y[i + 1], body_of(c, k), o.name,
            o.tie ? "tied extension" : "line", m->at.x, m->at.y,
            o.in_body ? "ties of two lines in one body that meet"
                      : "a crack heading for an interface between two bodies (a T-junction on the body's edge)"));
      }
}

}  // namespace rupture
