// rupture/input/parse_stations.cpp
// The [stations] table (output/stations.hpp): named points on a fault or in a body.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cohesive/polyline.hpp"
#include "input/case_parse.hpp"
#include "input/input_schema.hpp"

namespace rupture {

void parse_stations(Section& top, Case& c) {
  Section all = top.table("stations", false);
  for (const auto& [name, v] : named_entries(all)) {
    Section t = all.table(name, true, allowed_keys("stations.*"));
    StationSpec st;
    st.name = name;
    double at[2];
    t.pair("at", at, true);
    st.x = at[0], st.y = at[1];
    const double tol = 1e-9 * c.grid.cell_size;
    if (!inside(st.x, c.grid.min[0], c.grid.max[0], tol) ||
        !inside(st.y, c.grid.min[1], c.grid.max[1], tol))
      fail(t.key("at"), fmt::format("[{:g}, {:g}]", st.x, st.y),
           fmt::format("must lie in the grid [{:g}, {:g}]..[{:g}, {:g}]", c.grid.min[0],
                       c.grid.min[1], c.grid.max[0], c.grid.max[1]));
    if (t.has("interface")) {
      const std::string iface = t.string("interface", "");
      const auto it = std::find(c.interface_names.begin(), c.interface_names.end(), iface);
      if (it == c.interface_names.end())
        fail(t.key("interface"), "\"" + iface + "\"",
             "must name an [interface] entry: " + Section::join(c.interface_names));
      st.interface = int(it - c.interface_names.begin());
      const LineProjection p = project(c.interfaces[std::size_t(st.interface)].geometry(), st.x, st.y);
      if (p.distance > 0.5 * c.grid.cell_size || p.beyond > 0.5 * c.grid.cell_size)
        fail(t.key("at"), fmt::format("[{:g}, {:g}]", st.x, st.y),
             fmt::format("must lie on interface.{} (it is {:g} m off it; allowed: half a cell, "
                         "{:g} m)",
                         iface, std::max(p.distance, p.beyond), 0.5 * c.grid.cell_size));
    }
    const std::string read = t.string("read", "nearest", {"nearest", "interpolated"});
    st.interpolated = read == "interpolated";
    if (st.interpolated && st.interface >= 0)
      fail(t.key("read"), "\"interpolated\"",
           "applies to body stations (a fault station reads its line's two nodes around the point)");
    c.stations.push_back(st);
  }
}

}  // namespace rupture
