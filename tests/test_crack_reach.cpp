// Tests of input/crack_reach.hpp: which parts of a body a growing crack drawn in it does not
// reach (split off by other lines, on neither of its fields, changed by no growing line), and
// which lines lie on the edge of its reach (one face wholly on its fields, the other beyond).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "input/case_toml.hpp"
#include "input/crack_reach.hpp"

using namespace rupture;

namespace {

Case input(const std::string& name) { return load_case(std::string(RUPTURE_SOURCE_DIR) + "/" + name); }

std::size_t interface_named(const Case& c, const std::string& name) {
  return std::size_t(std::find(c.interface_names.begin(), c.interface_names.end(), name) - c.interface_names.begin());
}

int field_named(const Case& c, const std::string& body) {
  for (const BodySpec& b : c.bodies)
    if (b.name == body) return b.field;
  return -1;
}

}  // namespace

// A bonded line across the plate, then a cut below it whose tie ends on it: the part above the
// line is beyond the cut's reach, and the line is on its edge (the in-body form of two bonded
// plates).
TEST(CrackReach, a_line_across_the_plate_bounds_the_reach_of_a_crack_below_it) {
  const Case c = input("tests/inputs/wall_junction.toml");
  const std::size_t cut = interface_named(c, "cut"), bond = interface_named(c, "bond");
  EXPECT_EQ(fields_beyond_reach(c, cut), std::vector<int>{field_named(c, "plate")});
  EXPECT_TRUE(on_edge_of_reach(c, cut, c.interfaces[bond]));
}

// Drawn the other way round (the crack first, then an edge crack in the part below it): the part
// below the edge crack is beyond the crack's reach.
TEST(CrackReach, an_edge_crack_drawn_after_the_crack_bounds_its_reach) {
  const Case c = input("tests/inputs/crack_into_wall.toml");
  const std::size_t crack = interface_named(c, "crack"), wall = interface_named(c, "wall");
  EXPECT_EQ(fields_beyond_reach(c, crack), std::vector<int>{field_named(c, "plate.below.crack.below.wall")});
  EXPECT_TRUE(on_edge_of_reach(c, crack, c.interfaces[wall]));
}

// Two growing cracks in one beam (the notch and the mid-span seed): each changes the other's
// part, so nothing is beyond either's reach and neither line is an edge (a meeting stops).
TEST(CrackReach, parts_a_growing_line_changes_stay_within_reach) {
  const Case c = input("examples/john_shah.toml");
  ASSERT_EQ(c.interfaces.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_TRUE(fields_beyond_reach(c, k).empty()) << c.interface_names[k];
    EXPECT_FALSE(on_edge_of_reach(c, k, c.interfaces[1 - k])) << c.interface_names[k];
  }
}

// An interface between two bodies is not drawn in the crack's body: not an edge of its reach
// (it is the body's own edge), and the other body is no part of the crack's body.
TEST(CrackReach, an_interface_between_bodies_is_not_a_line_in_the_body) {
  const Case c = input("tests/inputs/bond_junction.toml");
  const std::size_t cut = interface_named(c, "cut"), bond = interface_named(c, "bond");
  EXPECT_TRUE(fields_beyond_reach(c, cut).empty());
  EXPECT_FALSE(on_edge_of_reach(c, cut, c.interfaces[bond]));
}
