// rupture/input/crack_reach.cpp
#include "input/crack_reach.hpp"

#include <algorithm>

namespace rupture {
namespace {

// Whether field f is a face of a growing line (or kept for its branches): its material changes
// as that line grows.
bool field_of_growing_line(const Case& c, int f) {
  for (const InterfaceSpec& e : c.interfaces) {
    if (!e.growth.on()) continue;
    if (e.upper_field == f || e.lower_field == f) return true;
    for (const auto* faces : {&e.upper_faces, &e.lower_faces})
      for (const FaceField& st : *faces)
        if (st.field == f) return true;
    for (const int b : e.branch_fields)
      if (b == f) return true;
  }
  return false;
}

// Whether a face (its stretches, or its whole field where it has none) lies wholly on fields
// `in` accepts.
template <class In>
bool face_on(const std::vector<FaceField>& faces, int whole, In in) {
  if (faces.empty()) return in(whole);
  return std::all_of(faces.begin(), faces.end(), [&](const FaceField& f) { return in(f.field); });
}

}  // namespace

std::vector<int> fields_beyond_reach(const Case& c, std::size_t k) {
  const InterfaceSpec& crack = c.interfaces[k];
  const Region& r = c.bodies[std::size_t(crack.upper_body)].region;
  std::vector<int> out;
  for (const BodySpec& b : c.bodies) {
    if (!same_drawn_region(b.region, r) || b.region.sides.empty()) continue;
    if (b.field == crack.upper_field || b.field == crack.lower_field) continue;
    if (field_of_growing_line(c, b.field)) continue;
    if (std::find(out.begin(), out.end(), b.field) == out.end()) out.push_back(b.field);
  }
  return out;
}

bool on_edge_of_reach(const Case& c, std::size_t k, const InterfaceSpec& e) {
  if (e.growth.on()) return false;
  const Region& r = c.bodies[std::size_t(c.interfaces[k].upper_body)].region;
  if (!same_drawn_region(c.bodies[std::size_t(e.upper_body)].region, r) ||
      !same_drawn_region(c.bodies[std::size_t(e.lower_body)].region, r))
    return false;
  const std::vector<int> beyond = fields_beyond_reach(c, k);
  const int fa = c.interfaces[k].upper_field, fb = c.interfaces[k].lower_field;
  const auto reach = [&](int f) { return f == fa || f == fb; };
  const auto past = [&](int f) { return std::find(beyond.begin(), beyond.end(), f) != beyond.end(); };
  return (face_on(e.upper_faces, e.upper_field, reach) && face_on(e.lower_faces, e.lower_field, past)) ||
         (face_on(e.lower_faces, e.lower_field, reach) && face_on(e.upper_faces, e.upper_field, past));
}

}  // namespace rupture
