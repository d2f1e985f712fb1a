// rupture/output/crack_xdmf.cpp
#include "output/crack_xdmf.hpp"

#include <fmt/format.h>

#include "core/atomic_file.hpp"

namespace rupture {

std::vector<std::array<double, 2>> crack_path_at(const Case& c, std::size_t k, const CrackGrowthRecord& growth,
                                                 double t) {
  const Polyline drawn = c.interfaces[k].geometry();
  const std::vector<GrowthRow>& r = growth.rows;
  std::vector<std::array<double, 2>> start, path;
  for (std::size_t i = 0; i < r.size() && r[i].time <= t; ++i)
    if (!r[i].split && r[i].tip < 2 && r[i].end == LineEnd::start) start.push_back({r[i].x, r[i].y});
  // The start's vertices were put in front one by one: the last made is the path's first.
  path.assign(start.rbegin(), start.rend());
  for (std::size_t v = 0; v < drawn.num_vertices(); ++v) path.push_back({drawn.x[v], drawn.y[v]});
  for (std::size_t i = 0; i < r.size() && r[i].time <= t; ++i)
    if (!r[i].split && r[i].tip < 2 && r[i].end == LineEnd::end) path.push_back({r[i].x, r[i].y});
  return path;
}

std::vector<std::vector<std::array<double, 2>>> crack_branches_at(const CrackGrowthRecord& growth, double t) {
  const std::vector<GrowthRow>& r = growth.rows;
  std::vector<std::vector<std::array<double, 2>>> branches;
  std::array<double, 2> split{};
  for (std::size_t i = 0; i < r.size() && r[i].time <= t; ++i) {
    if (r[i].split) {
      split = {r[i].x, r[i].y};
      continue;
    }
    if (r[i].tip < 2) continue;
    const std::size_t b = std::size_t(r[i].tip) - 2;
    if (b >= branches.size()) branches.resize(b + 1);
    if (branches[b].empty()) branches[b].push_back(split);  // its first row follows its split
    branches[b].push_back({r[i].x, r[i].y});
  }
  return branches;
}

std::string cracks_xdmf(const Case& c, const std::vector<CrackGrowthRecord>& growth,
                        const std::vector<double>& times) {
  std::string grids;
  for (std::size_t k = 0; k < c.interfaces.size() && k < growth.size(); ++k) {
    if (!c.interfaces[k].growth.on()) continue;
    grids += fmt::format("    <Grid Name=\"crack_{}\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
                         c.interface_names[k]);
    for (std::size_t j = 0; j < times.size(); ++j) {
      // The path and its branches, each a chain of two-node cells over the shared points.
      std::vector<std::vector<std::array<double, 2>>> chains{crack_path_at(c, k, growth[k], times[j])};
      for (auto& b : crack_branches_at(growth[k], times[j])) chains.push_back(std::move(b));
      std::string cells, points;
      std::size_t n = 0, segments = 0;
      for (const auto& chain : chains) {
        for (std::size_t v = 0; v + 1 < chain.size(); ++v) cells += fmt::format(" {} {}", n + v, n + v + 1), ++segments;
        for (const auto& q : chain) points += fmt::format(" {:.9e} {:.9e} 0", q[0], q[1]);
        n += chain.size();
      }
      grids += fmt::format(
          "      <Grid Name=\"step{}\" GridType=\"Uniform\">\n"
          "        <Time Value=\"{:.9e}\"/>\n"
          "        <Topology TopologyType=\"Polyline\" NumberOfElements=\"{}\" NodesPerElement=\"2\">\n"
          "          <DataItem Dimensions=\"{} 2\" NumberType=\"Int\" Format=\"XML\">{}</DataItem>\n"
          "        </Topology>\n"
          "        <Geometry GeometryType=\"XYZ\">\n"
          "          <DataItem Dimensions=\"{} 3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">{}</DataItem>\n"
          "        </Geometry>\n"
          "      </Grid>\n",
          j, times[j], segments, segments, cells, n, points);
    }
    grids += "    </Grid>\n";
  }
  if (grids.empty() || times.empty()) return "";
  return "<?xml version=\"1.0\" ?>\n"
         "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
         "<Xdmf Version=\"3.0\">\n"
         "  <Domain>\n" +
         grids + "  </Domain>\n</Xdmf>\n";
}

void write_cracks_xdmf(const std::string& dir, const Case& c, const std::vector<CrackGrowthRecord>& growth,
                       const std::vector<double>& times) {
  const std::string x = cracks_xdmf(c, growth, times);
  if (!x.empty()) write_file_atomic(dir + "/cracks.xdmf", x);
}

}  // namespace rupture
