// Tests of input/parameters.hpp: the expression grammar (precedence, unary signs, powers,
// functions, pi), whole results as integers, the substitution everywhere in a case (tables,
// arrays, nested arrays) but the title and [parameters], --set moving what depends on a
// parameter, and every bad expression or parameter named with its key.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "input/parameters.hpp"

namespace rupture {
namespace {

double eval(const std::string& text, const std::map<std::string, double>& names = {}) {
  return evaluate_expression(text, names, "k");
}

std::string error_of(const std::string& text, const std::map<std::string, double>& names = {}) {
  try {
    eval(text, names);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Parameters, ArithmeticFollowsTheUsualPrecedence) {
  EXPECT_DOUBLE_EQ(eval("1 + 2 * 3"), 7.0);
  EXPECT_DOUBLE_EQ(eval("(1 + 2) * 3"), 9.0);
  EXPECT_DOUBLE_EQ(eval("8 / 4 / 2"), 1.0);       // left to right
  EXPECT_DOUBLE_EQ(eval("2 ^ 3 ^ 2"), 512.0);      // right to left
  EXPECT_DOUBLE_EQ(eval("-2 ^ 2"), -4.0);          // the sign applies to the power
  EXPECT_DOUBLE_EQ(eval("2 * -3"), -6.0);
  EXPECT_DOUBLE_EQ(eval("1.5e3 + .5 + 2E-1"), 1500.7);
  EXPECT_DOUBLE_EQ(eval("sqrt(16) + abs(-2) + exp(0) + log(1)"), 7.0);
  EXPECT_NEAR(eval("sin(pi / 6) + cos(0) + tan(pi / 4) + atan(1) * 4 / pi"), 3.5, 1e-15);
  EXPECT_DOUBLE_EQ(eval("0.128 - offset * half", {{"offset", 0.5}, {"half", 0.1016}}), 0.128 - 0.5 * 0.1016);
}

TEST(Parameters, BadExpressionsAreNamedWithTheirReason) {
  const std::map<std::string, double> p = {{"a", 1.0}, {"b", 2.0}};
  EXPECT_NE(error_of("a + c", p).find("unknown name 'c' (the parameters are a b)"), std::string::npos);
  EXPECT_NE(error_of("x").find("no [parameters] are defined"), std::string::npos);
  EXPECT_NE(error_of("1 / 0").find("must be finite"), std::string::npos);
  EXPECT_NE(error_of("sqrt(-1)").find("must be finite"), std::string::npos);
  EXPECT_NE(error_of("(1 + 2").find("'(' is not closed"), std::string::npos);
  EXPECT_NE(error_of("1 + ").find("ends where a value was expected"), std::string::npos);
  EXPECT_NE(error_of("1 2").find("unexpected '2'"), std::string::npos);
  EXPECT_NE(error_of("floor(1.5)").find("unknown function 'floor'"), std::string::npos);
  EXPECT_NE(error_of("1e").find("exponent without digits"), std::string::npos);
  EXPECT_NE(error_of(std::string(200, '(') + "1" + std::string(200, ')')).find("nested deeper than 64"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(200, '-') + "1").find("nested deeper than 64"), std::string::npos);
  const std::string m = error_of("a +* b", p);
  EXPECT_NE(m.find("input key 'k' = \"=a +* b\""), std::string::npos) << m;
}

constexpr const char* kCase = R"(title = "=not an expression"
[parameters]
h = 1e-3
offset = 0.5
[materials.m]
youngs_modulus = "=5.2e9 * 1"
poisson_ratio = 0.34
density = 1246.0
[grid]
min = [0.0, 0.0]
max = ["=256 * h", "=76 * h"]
cell_size = "=h"
[bodies.beam]
material = "m"
min = [0.0, 0.0]
max = ["=0.256", 0.076]
[interface.notch]
body = "beam"
points = [["=0.128 - offset * 0.1016", 0.0], ["=0.128 - offset * 0.1016", "=0.019"]]
segments = "=0.019 / h"
law = "contact"
[time]
end = 1e-6
)";

TEST(Parameters, ACaseTakesItsValuesFromItsParametersAndSetMovesThem) {
  const Case c = parse_case(kCase);
  EXPECT_EQ(c.title, "=not an expression");  // the title is text
  EXPECT_DOUBLE_EQ(c.grid.cell_size, 1e-3);
  EXPECT_DOUBLE_EQ(c.grid.max[0], 0.256);
  EXPECT_DOUBLE_EQ(c.materials[0].youngs_modulus, 5.2e9);
  ASSERT_EQ(c.interfaces.size(), 1u);
  EXPECT_EQ(c.interfaces[0].segments, 19);  // 0.019 / 1e-3, within round-off of 19: an integer
  EXPECT_DOUBLE_EQ(c.interfaces[0].line.x[0], 0.128 - 0.5 * 0.1016);
  // A parameter may be an expression of others, written in any order.
  const Case chained = parse_case(kCase, {"parameters.offset=\"=a_half + quarter\"", "parameters.quarter=\"=a_half / 2\"",
                                          "parameters.a_half=0.5"});
  EXPECT_DOUBLE_EQ(chained.interfaces[0].line.x[0], 0.128 - 0.75 * 0.1016);
  const Case moved = parse_case(kCase, {"parameters.offset=0.75"});
  EXPECT_DOUBLE_EQ(moved.interfaces[0].line.x[0], 0.128 - 0.75 * 0.1016);
  EXPECT_DOUBLE_EQ(moved.interfaces[0].line.x[1], 0.128 - 0.75 * 0.1016);
  // The run's input echo holds the values the run used.
  EXPECT_NE(c.input_toml.find("0.0772"), std::string::npos);
  EXPECT_EQ(c.input_toml.find("offset * 0.1016"), std::string::npos);
}

TEST(Parameters, BadParametersAreNamed) {
  auto error = [](const std::vector<std::string>& sets) {
    try {
      parse_case(kCase, sets);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error({"parameters.offset=true"}).find("'parameters.offset' = true: must be a finite number"),
            std::string::npos);
  EXPECT_NE(error({"parameters.offset=\"=2 * b\"", "parameters.b=\"=offset\""}).find("depend on one another in a circle"),
            std::string::npos);
  EXPECT_NE(error({"parameters.offset=\"=2 * nope\""}).find("'parameters.offset' = \"=2 * nope\": the expression: unknown name 'nope'"),
            std::string::npos);
  EXPECT_NE(error({"parameters.pi=3"}).find("'pi' is the constant"), std::string::npos);
  EXPECT_NE(error({"parameters=3"}).find("'parameters' = 3: must be a table"), std::string::npos);
  EXPECT_NE(error({"grid.cell_size=\"=2 * hh\""}).find("'grid.cell_size' = \"=2 * hh\": the expression: unknown name 'hh'"),
            std::string::npos);
  EXPECT_NE(error({"interface.notch.points=[[\"=1/0\", 0.0], [0.1, 0.0]]"}).find("'interface.notch.points[0][0]'"),
            std::string::npos);
  EXPECT_NE(error({"interface.notch.segments=\"=19.5\""}).find("segments"), std::string::npos);  // not whole
}

}  // namespace
}  // namespace rupture
