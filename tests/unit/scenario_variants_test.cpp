// RIG-5: a scenario run once per variant (`variants:`), the variants
// compared (`compare:`): the loader and the comparison check.
#include <catch2/catch.hpp>

#include "config_error.hpp"
#include "scenario_set.hpp"
#include "variant_comparison.hpp"

using namespace hil;

namespace {

const std::string inline_machine = "{cycle_time_us: 1000, axes: [{name: X, v_max: 100, a_max: 1000, j_max: 10000, "
                                   "kv: 40, velocity_lag_s: 0.002}, {name: Z, v_max: 100, a_max: 1000, "
                                   "j_max: 10000, kv: 40, velocity_lag_s: 0.002}]}";

ScenarioSet set_of(const std::string& rest) {
  return load_scenario_set_node(YAML::Load("name: cmp\nnc_program: \"G01 X1 F100\\n\"\n" + rest), "dir/s.yaml");
}

std::string two_variants() {
  return "variants:\n  - {name: fast, machine: " + inline_machine + "}\n  - {name: slow, machine: " + inline_machine +
         "}\n";
}

}  // namespace

TEST_CASE("RIG-5 variants: one scenario per variant, named <scenario>.<variant>, compare entries read",
          "[scenario][variants]") {
  const ScenarioSet set =
      set_of(two_variants() + "compare:\n  - {axis_max_mm: Z, greater: fast, than: slow, by_at_least_mm: 1}\n");
  REQUIRE(set.has_variants());
  REQUIRE(set.variants.size() == 2);
  CHECK(set.name == "cmp");
  CHECK(set.variants[0].name == "fast");
  CHECK(set.variants[0].scenario.name == "cmp.fast");
  CHECK(set.variants[1].scenario.machine.axes.size() == 2);
  // The nodes read a scenario without the keys only hil run knows.
  CHECK_FALSE(set.variants[0].scenario.resolved["variants"]);
  CHECK_FALSE(set.variants[0].scenario.resolved["compare"]);
  REQUIRE(set.comparisons.size() == 1);
  CHECK(set.comparisons[0].key == "axis_max_mm");
  CHECK(set.comparisons[0].axis == "Z");
  CHECK(set.comparisons[0].by_at_least_mm == 1);
}

TEST_CASE("RIG-5 variants: without variants a scenario is one run, as before", "[scenario][variants]") {
  const ScenarioSet set = set_of("machine: " + inline_machine + "\n");
  CHECK_FALSE(set.has_variants());
  REQUIRE(set.variants.size() == 1);
  CHECK(set.variants[0].scenario.name == "cmp");
}

TEST_CASE("RIG-5 variants: wrong variants and comparisons are refused with their place", "[scenario][variants]") {
  CHECK_THROWS_WITH(set_of("machine: " + inline_machine + "\n" + two_variants()),
                    Catch::Contains("machine: give it in each variant"));
  CHECK_THROWS_WITH(set_of("machine: " + inline_machine + "\ncompare: []\n"), Catch::Contains("compare: needs variants"));
  CHECK_THROWS_WITH(set_of("variants:\n  - {name: a, machin: " + inline_machine + "}\n"),
                    Catch::Contains("variants[0].machin: unknown key, did you mean machine?"));
  CHECK_THROWS_WITH(set_of("variants:\n  - {name: a/b, machine: " + inline_machine + "}\n"),
                    Catch::Contains("variants[0].name: letters, digits"));
  CHECK_THROWS_WITH(set_of("variants:\n  - {name: a, machine: " + inline_machine + "}\n  - {name: a, machine: " +
                           inline_machine + "}\n"),
                    Catch::Contains("'a' given twice"));
  CHECK_THROWS_WITH(set_of("variants: []\n"), Catch::Contains("variants: must be a list"));
  CHECK_THROWS_WITH(set_of(two_variants() + "compare:\n  - {axis_max_mm: Z, greater: fast, than: medium}\n"),
                    Catch::Contains("compare[0].than: 'medium' is no variant"));
  CHECK_THROWS_WITH(set_of(two_variants() + "compare:\n  - {axis_max_mm: Y, greater: fast, than: slow}\n"),
                    Catch::Contains("axis 'Y' is not on the machine of variant fast"));
  CHECK_THROWS_WITH(set_of(two_variants() + "compare:\n  - {axis_max_mm: Z, axis_min_mm: Z, greater: fast, than: slow}\n"),
                    Catch::Contains("not both"));
  CHECK_THROWS_WITH(set_of(two_variants() + "compare:\n  - {axis_max: Z, greater: fast, than: slow}\n"),
                    Catch::Contains("compare[0].axis_max: unknown key, did you mean axis_max_mm?"));
  CHECK_THROWS_WITH(set_of(two_variants() + "compare:\n  - {axis_max_mm: Z, greater: fast, than: fast}\n"),
                    Catch::Contains("the same variant"));
  // A variant's own errors name the variant.
  CHECK_THROWS_WITH(set_of("variants:\n  - {name: a, machine: {cycle_time_us: 1000, axes: [{name: X, v_mx: 1}]}}\n"),
                    Catch::Contains("(variant a)"));
}

TEST_CASE("RIG-5 variants: a comparison holds only when the one variant exceeds the other", "[scenario][variants]") {
  rig::VariantFigures a, b;
  a.name = "advanced";
  b.name = "lifting";
  a.axes = b.axes = {"Z"};
  a.max_mm = {38};
  b.max_mm = {25};
  a.min_mm = {10};
  b.min_mm = {12};
  bool hold = false;
  const std::string text = rig::check_comparisons({a, b}, {{"axis_max_mm", "Z", "advanced", "lifting", 0}}, hold);
  CHECK(hold);
  CHECK_THAT(text, Catch::Contains("advanced 38.000 mm > lifting 25.000 mm (difference 13.000 mm): holds"));
  rig::check_comparisons({a, b}, {{"axis_max_mm", "Z", "advanced", "lifting", 20}}, hold);
  CHECK_FALSE(hold);
  rig::check_comparisons({a, b}, {{"axis_max_mm", "Z", "lifting", "advanced", 0}}, hold);
  CHECK_FALSE(hold);
  // axis_min_mm: "greater" went further down.
  rig::check_comparisons({a, b}, {{"axis_min_mm", "Z", "advanced", "lifting", 0}}, hold);
  CHECK(hold);
  rig::check_comparisons({a, b}, {{"axis_max_mm", "Z", "advanced", "missing", 0}}, hold);
  CHECK_FALSE(hold);
}
