// rupture/io/parse_interfaces.cpp
// The [interface] table: cohesive interfaces, their law and bonded stretch (SPEC §3).
#include <fmt/format.h>

#include <cmath>

#include "io/case_parse.hpp"

namespace rupture {

void parse_interfaces(Section& top, Case& c, ParseContext& ctx) {
  auto& body_index = ctx.body_index;
  Section ifs = top.table("interface", false);
  for (const auto& [k, v] : in_input_order(ifs.raw())) {
    const std::string& name = k;
    Section f = ifs.table(
        name, true,
        {"upper_body", "lower_body", "y", "start", "end", "segments", "sigma_max", "tau_max",
         "delta_n", "delta_t", "q", "r", "penalty", "separation", "bonded_to"});
    InterfaceSpec is;
    std::vector<std::string> names;
    for (const auto& bb : c.bodies) names.push_back(bb.name);
    for (const char* which : {"upper_body", "lower_body"}) {
      const std::string body = f.string(which, "");
      if (!body_index.count(body))
        fail(f.key(which), "\"" + body + "\"", "must name a body among " + Section::join(names));
      (std::string(which) == "upper_body" ? is.upper_body : is.lower_body) = body_index[body];
    }
    if (is.upper_body == is.lower_body)
      fail(f.key("lower_body"), "\"" + c.bodies[is.lower_body].name + "\"",
           "must differ from upper_body");
    const BodySpec &up = c.bodies[is.upper_body], &lo = c.bodies[is.lower_body];
    is.upper_field = up.field;
    is.lower_field = lo.field;
    // The interface joins two velocity fields: bodies of one field are one continuum.
    if (up.field == lo.field)
      fail(f.key("lower_body"), "\"" + lo.name + "\"",
           fmt::format("bodies.{} and bodies.{} share the velocity field \"{}\" (one continuum): "
                       "an interface must join bodies of two different fields (give one of them "
                       "its own bodies.NAME.field)",
                       up.name, lo.name, c.field_names[std::size_t(up.field)]));
    is.y = f.number("y");
    const double tol = 1e-9 * c.grid.cell_size;
    if (std::fabs(up.min[1] - is.y) > tol || std::fabs(lo.max[1] - is.y) > tol)
      fail(f.key("y"), is.y,
           fmt::format(
               "must be the bottom of the upper body ({:g}) and the top of the lower body ({:g})",
               up.min[1], lo.max[1]));
    is.start = f.number("start");
    is.end = f.number("end");
    const double x0 = std::max(up.min[0], lo.min[0]), x1 = std::min(up.max[0], lo.max[0]);
    if (!inside(is.start, x0, x1, tol))
      fail(f.key("start"), is.start,
           fmt::format("must lie where both bodies meet: [{:g}, {:g}] m", x0, x1));
    if (!(is.end > is.start) || !inside(is.end, x0, x1, tol))
      fail(f.key("end"), is.end, fmt::format("must lie in ({:g}, {:g}] m", is.start, x1));
    const long segments = f.integer("segments", -1);
    if (segments < 1 || segments > 100000000)
      fail(f.key("segments"), double(segments), "required, an integer in [1, 1e8]");
    is.segments = int(segments);
    XuNeedleman& law = is.law;
    law.sigma_max = f.number("sigma_max");
    if (law.sigma_max <= 0) fail(f.key("sigma_max"), law.sigma_max, "must be > 0 (Pa)");
    law.tau_max = f.number("tau_max", law.sigma_max);
    if (law.tau_max <= 0) fail(f.key("tau_max"), law.tau_max, "must be > 0 (Pa)");
    law.delta_n = f.number("delta_n");
    if (law.delta_n <= 0) fail(f.key("delta_n"), law.delta_n, "must be > 0 (m)");
    law.q = f.number("q", 1.0);
    if (law.q <= 0) fail(f.key("q"), law.q, "must be > 0");
    law.r = f.number("r", 0.0);
    if (law.r < 0 || std::fabs(law.r - 1.0) < 1e-12)
      fail(f.key("r"), law.r, "must be >= 0 and differ from 1");
    if (f.has("delta_t")) {
      law.delta_t = f.number("delta_t");
      if (law.delta_t <= 0) fail(f.key("delta_t"), law.delta_t, "must be > 0 (m)");
    } else {
      // q = phi_t/phi_n with phi_t = sqrt(e/2) tau_max delta_t, phi_n = e sigma_max delta_n.
      law.delta_t = law.q * std::exp(1.0) * law.sigma_max * law.delta_n /
                    (std::sqrt(std::exp(1.0) / 2.0) * law.tau_max);
    }
    law.penalty = f.number("penalty", 1.0);
    if (law.penalty < 0)
      fail(f.key("penalty"), law.penalty, "must be >= 0 (multiple of phi_n/delta_n^2)");
    is.separation_factor = f.number("separation", 5.0);
    if (!(is.separation_factor > 0 && is.separation_factor <= 1000))
      fail(f.key("separation"), is.separation_factor,
           "must lie in (0, 1000] (multiples of delta_t)");
    if (f.has("bonded_to")) {
      is.bonded = true;
      is.bonded_from = is.end;
      is.bonded_to = f.number("bonded_to");
      if (!(is.bonded_to > is.end) || !inside(is.bonded_to, x0, x1, tol))
        fail(f.key("bonded_to"), is.bonded_to,
             fmt::format("must lie in ({:g}, {:g}] m (the halves are tied from end to here)",
                         is.end, x1));
    }
    c.interfaces.push_back(is);
    c.interface_names.push_back(name);
  }
}

}  // namespace rupture
