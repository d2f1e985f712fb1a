// Tests of the table of traction laws (input/law_registry.hpp): every law has one entry of
// its own name, in the order and with the default that the input reference gives law = ...;
// every alternative of CohesiveLaw has exactly one entry (law_name is its name); each entry's
// keys are exactly those input/input_schema.cpp documents for that law; its parser accepts a
// table of its documented examples (with the keys its law requires besides, as the schema
// says) and refuses every key of another law by name; and its hooks answer (`rupture check`'s
// words, the node traction). Why: the generic code asks the table instead of comparing names,
// so an entry that drifts from the schema or the parser would accept or refuse the wrong keys,
// or describe an interface as another law.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "cohesive/interface.hpp"
#include "input/law_registry.hpp"
#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "input/input_schema.hpp"
#include "output/interface_csv.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

// Two bodies of their own fields joined by [interface.w] along y = 0 (tests/support.hpp) with
// `lines` (the law and its keys).
std::string case_with(const std::string& lines) { return test::case_with(test::kGeometry + lines); }

std::string error_of(const std::string& lines) {
  try {
    parse_case(case_with(lines));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const KeyDoc& doc(const std::string& key) {
  const KeyDoc* d = find_key("interface.*." + key);
  EXPECT_NE(d, nullptr) << key;
  static const KeyDoc none;
  return d ? *d : none;
}

// law = NAME and each of the law's keys at its documented example (an array of tables,
// documented without one, left out), with the keys the schema says the law requires besides
// (law = "contact": contact_stiffness).
std::string examples_of(const LawEntry& law) {
  std::string lines = "law = \"" + law.name + "\"\n";
  for (const std::string& k : law.keys)
    if (!doc(k).example.empty()) lines += k + " = " + doc(k).example + "\n";
  const std::string required = "required with law = \"" + law.name + "\"";
  for (const std::string& k : allowed_keys("interface.*"))
    if (!law.has_key(k) && doc(k).default_value.find(required) != std::string::npos)
      lines += k + " = " + doc(k).example + "\n";
  return lines;
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

}  // namespace

TEST(LawRegistry, names_are_unique_and_the_schema_lists_them_in_order) {
  const std::vector<LawEntry>& laws = law_registry();
  ASSERT_FALSE(laws.empty());
  std::set<std::string> names;
  std::string values;
  for (const LawEntry& e : laws) {
    EXPECT_TRUE(names.insert(e.name).second) << "two entries named " << e.name;
    EXPECT_FALSE(e.description.empty()) << e.name;
    EXPECT_TRUE(e.parse && e.describe && e.node_traction) << e.name << ": a hook is missing";
    EXPECT_EQ(find_law(e.name), &e);
    values += (values.empty() ? "" : ", ") + quoted(e.name);
  }
  EXPECT_EQ(find_law("no_such_law"), nullptr);
  EXPECT_EQ(law_names().size(), laws.size());
  // interface.*.law: the table's names in its order, the first the default.
  const KeyDoc& law = doc("law");
  EXPECT_EQ(law.range, values);
  EXPECT_EQ(law.default_value, quoted(laws.front().name));
  EXPECT_EQ(laws.front().name, "xu_needleman");  // the paper's law, the input's default
  // A case without `law` gets the first entry's law.
  const Case c = parse_case(case_with("sigma_max = 24e6\ndelta_n = 0.4e-6\n"));
  EXPECT_EQ(&law_entry(c.interfaces.at(0)), &laws.front());
}

TEST(LawRegistry, every_law_alternative_has_exactly_one_entry) {
  std::size_t without = 0;
  for (const LawEntry& e : law_registry()) {
    EXPECT_GE(e.alternative, -1) << e.name;
    EXPECT_LT(e.alternative, int(std::variant_size_v<CohesiveLaw>)) << e.name;
    without += e.alternative < 0 ? 1 : 0;
  }
  EXPECT_LE(without, 1u) << "at most one law without a cohesive law (the pre-crack)";
  auto check = [](auto index) {
    constexpr std::size_t I = decltype(index)::value;
    int count = 0;
    for (const LawEntry& e : law_registry()) count += e.alternative == int(I) ? 1 : 0;
    EXPECT_EQ(count, 1) << "alternative " << I;
    const CohesiveLaw law{std::in_place_index<I>};
    EXPECT_EQ(law_entry(law).alternative, int(I));
    EXPECT_EQ(std::string(law_name(law)), law_entry(law).name);
  };
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (check(std::integral_constant<std::size_t, I>{}), ...);
  }(std::make_index_sequence<std::variant_size_v<CohesiveLaw>>{});
  EXPECT_EQ(law_alternative<XuNeedleman>(), 0);
  EXPECT_EQ(law_alternative<ContactLaw>(), -1);  // not a cohesive law
}

TEST(LawRegistry, keys_are_those_the_schema_documents_for_the_law) {
  // As sets: an entry lists its keys in the order they are refused with another law.
  for (const LawEntry& e : law_registry()) {
    std::vector<std::string> listed = e.keys, documented = variant_keys("interface.*", "law", e.name);
    std::sort(listed.begin(), listed.end());
    std::sort(documented.begin(), documented.end());
    EXPECT_EQ(listed, documented) << e.name;
    EXPECT_EQ(std::set<std::string>(listed.begin(), listed.end()).size(), listed.size()) << e.name;
  }
}

TEST(LawRegistry, parser_accepts_the_documented_examples) {
  for (const LawEntry& e : law_registry()) {
    const std::string lines = examples_of(e);
    ASSERT_EQ(error_of(lines), "") << e.name << ":\n" << lines;
    const Case c = parse_case(case_with(lines));
    const InterfaceSpec& is = c.interfaces.at(0);
    EXPECT_EQ(&law_entry(is), &e) << e.name;
    if (e.alternative >= 0) {
      EXPECT_EQ(int(is.law.index()), e.alternative) << e.name;
    }
    EXPECT_FALSE(e.describe(is).empty()) << e.name;
  }
}

TEST(LawRegistry, parser_refuses_every_key_of_another_law) {
  for (const LawEntry& e : law_registry()) {
    const std::string lines = examples_of(e);
    int refused = 0;
    for (const LawEntry& other : law_registry())
      for (const std::string& k : other.keys) {
        if (e.has_key(k)) continue;
        const std::string value = doc(k).example.empty() ? "[]" : doc(k).example;
        const std::string error = error_of(lines + k + " = " + value + "\n");
        EXPECT_NE(error.find("'interface.w." + k + "'"), std::string::npos) << e.name << ", " << k << ": " << error;
        EXPECT_NE(error.find("not a parameter of law = " + quoted(e.name)), std::string::npos)
            << e.name << ", " << k << ": " << error;
        ++refused;
      }
    EXPECT_GT(refused, 0) << e.name << " refuses no key of another law";
  }
}

TEST(LawRegistry, node_traction_is_the_laws) {
  // At rest: a cohesive law's traction at zero jump is zero; a fault reports its prestress.
  const LawEntry& fault = *find_law("slip_weakening");
  const Case c = parse_case(case_with(examples_of(fault)));
  const CohesiveInterface ci = make_interface(c.interfaces.at(0));
  const SlipWeakening& sw = std::get<SlipWeakening>(ci.spec.law);
  for (std::size_t k = 0; k < ci.num_nodes(); ++k) {
    const CohesiveTraction t = node_traction(ci, k);
    EXPECT_EQ(t.normal, sw.tn0);
    EXPECT_EQ(t.tangential, sw.tt0);
  }
  const Case x = parse_case(case_with(examples_of(*find_law("xu_needleman"))));
  const CohesiveInterface cx = make_interface(x.interfaces.at(0));
  for (std::size_t k = 0; k < cx.num_nodes(); ++k) {
    EXPECT_EQ(node_traction(cx, k).normal, 0.0);
    EXPECT_EQ(node_traction(cx, k).tangential, 0.0);
  }
}
