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

VariantComparison extreme(const std::string& key, const std::string& greater, const std::string& than, double by) {
  VariantComparison c;
  c.key = key;
  c.axis = "Z";
  c.greater = greater;
  c.than = than;
  c.by_at_least_mm = by;
  return c;
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
  CHECK_THROWS_WITH(set_of("variants:\n  - {name: a, machine: " + inline_machine + "}\n  - {name: b}\n"),
                    Catch::Contains("variants[1].machine: variant b has no machine"));
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
  const std::string text = rig::check_comparisons({a, b}, {extreme("axis_max_mm", "advanced", "lifting", 0)}, hold);
  CHECK(hold);
  CHECK_THAT(text, Catch::Contains("advanced 38.000 mm > lifting 25.000 mm (difference 13.000 mm): holds"));
  rig::check_comparisons({a, b}, {extreme("axis_max_mm", "advanced", "lifting", 20)}, hold);
  CHECK_FALSE(hold);
  rig::check_comparisons({a, b}, {extreme("axis_max_mm", "lifting", "advanced", 0)}, hold);
  CHECK_FALSE(hold);
  // axis_min_mm: "greater" went further down.
  rig::check_comparisons({a, b}, {extreme("axis_min_mm", "advanced", "lifting", 0)}, hold);
  CHECK(hold);
  rig::check_comparisons({a, b}, {extreme("axis_max_mm", "advanced", "missing", 0)}, hold);
  CHECK_FALSE(hold);
}

TEST_CASE("RIG-5 DPS-3 variants: the file's machine for variants without one; a variant's own timeline and expectations",
          "[scenario][variants][DPS-3]") {
  const ScenarioSet set = set_of(
      "machine: " + inline_machine +
      "\nplc:\n  m_function_ack_cycles: 3\n  timeline:\n    - when: {cycle: 5}\n      set: {program_start.enable_w: true, "
      "program_start.command_w: true}\n"
      "expect:\n  - when: program_end\n    axis_position_mm: {X: 1}\n"
      "variants:\n  - {name: plain}\n"
      "  - name: held\n    plc:\n      timeline:\n        - when: {cycle: 7}\n          set: {program_start.enable_w: "
      "true, program_start.command_w: true}\n        - when: {dist_prog_start_mm: 0.5}\n          set: "
      "{feedhold.enable_w: true, feedhold.command_w: true}\n"
      "    expect:\n      - when: {dist_prog_start_mm: 0.5}\n        channel_state: ACTIVE\n"
      "  - {name: other, machine: {cycle_time_us: 2000, axes: [{name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, "
      "velocity_lag_s: 0.002}, {name: Z, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}]}}\n"
      "compare:\n  - same_path: {reference: plain, variant: held, from_dist_mm: 0.25}\n"
      "  - same_path: {reference: plain, variant: other, tolerance_mm: 0.01}\n");
  REQUIRE(set.variants.size() == 3);
  const Scenario& plain = set.variants[0].scenario;
  const Scenario& held = set.variants[1].scenario;
  const Scenario& other = set.variants[2].scenario;
  CHECK(plain.machine.cycle_time_us == 1000);
  CHECK(other.machine.cycle_time_us == 2000);
  // plc: the variant's timeline replaces the file's; keys it does not give stay.
  REQUIRE(plain.timeline.size() == 1);
  REQUIRE(held.timeline.size() == 2);
  CHECK(held.m_function_ack_cycles == 3);
  CHECK(other.timeline.size() == 1);
  // expect: the variant's come after the file's.
  CHECK(plain.expectations.size() == 1);
  CHECK(held.expectations.size() == 2);
  // What the nodes read: the resolved scenario of the variant, without variants / compare.
  CHECK(held.resolved["plc"]["timeline"].size() == 2);
  CHECK(held.resolved["expect"].size() == 2);
  CHECK_FALSE(held.resolved["variants"]);
  CHECK_FALSE(held.resolved["compare"]);
  REQUIRE(set.comparisons.size() == 2);
  CHECK(set.comparisons[0].key == "same_path");
  CHECK(set.comparisons[0].reference == "plain");
  CHECK(set.comparisons[0].variant == "held");
  CHECK(set.comparisons[0].from_dist_mm == 0.25);
  CHECK(set.comparisons[0].tolerance_mm == 0.001);  // the default
  CHECK(set.comparisons[1].from_dist_mm == 0);
  CHECK(set.comparisons[1].tolerance_mm == 0.01);
}

TEST_CASE("RIG-5 DPS-3 variants: wrong plc, expect and same_path entries are refused with their place",
          "[scenario][variants][DPS-3]") {
  const std::string machine = "machine: " + inline_machine + "\n";
  CHECK_THROWS_WITH(set_of(machine + "variants:\n  - {name: a, timeline: []}\n"),
                    Catch::Contains("variants[0].timeline: unknown key"));
  CHECK_THROWS_WITH(set_of(machine + "variants:\n  - {name: a, plc: [1]}\n"),
                    Catch::Contains("variants[0].plc: must be a mapping"));
  CHECK_THROWS_WITH(set_of(machine + "variants:\n  - {name: a, expect: {when: program_end}}\n"),
                    Catch::Contains("variants[0].expect: must be a list"));
  CHECK_THROWS_WITH(set_of(machine + "variants:\n  - {name: a, plc: {timelin: []}}\n"),
                    Catch::Contains("plc.timelin: unknown key, did you mean timeline?") &&
                        Catch::Contains("(variant a; its plc: keys stand in plc)"));
  CHECK_THROWS_WITH(set_of(machine + "expect: [{when: program_end, channel_state: PROGRAM_END}]\n"
                                     "variants:\n  - {name: a, expect: [{when: program_end, chanel_state: ERROR}]}\n"),
                    Catch::Contains("expect[1].chanel_state: unknown key") &&
                        Catch::Contains("its expect: entries follow the file's 1"));
  const std::string two = machine + "variants:\n  - {name: a}\n  - {name: b}\n";
  CHECK_THROWS_WITH(set_of(two + "compare:\n  - same_path: {reference: a, variant: c}\n"),
                    Catch::Contains("compare[0].same_path.variant: 'c' is no variant"));
  CHECK_THROWS_WITH(set_of(two + "compare:\n  - same_path: {reference: a, variant: a}\n"),
                    Catch::Contains("the same variant"));
  CHECK_THROWS_WITH(set_of(two + "compare:\n  - same_path: {reference: a, variant: b, tolerance: 1}\n"),
                    Catch::Contains("compare[0].same_path.tolerance: unknown key, did you mean tolerance_mm?"));
  CHECK_THROWS_WITH(set_of(two + "compare:\n  - same_path: {reference: a, variant: b, tolerance_mm: -1}\n"),
                    Catch::Contains("compare[0].same_path.tolerance_mm"));
  CHECK_THROWS_WITH(set_of(two + "compare:\n  - same_path: {reference: a, variant: b}\n    greater: a\n"),
                    Catch::Contains("compare[0].greater: not with same_path"));
  CHECK_THROWS_WITH(
      set_of(two + "  - {name: c, machine: {cycle_time_us: 1000, axes: [{name: X, v_max: 100, a_max: 1000, j_max: "
                   "10000, kv: 40, velocity_lag_s: 0.002}]}}\ncompare:\n  - same_path: {reference: a, variant: c}\n"),
      Catch::Contains("different axes"));
}
