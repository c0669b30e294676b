// LIFT-2, LIFT-3, LIFT-4: the lift function's machine parameters
// P-STUP-00060 / 00070, P-CHAN-00345 and P-CHAN-00244
// (TF5200_lift_function.txt 4.2) and their refusals.
#include <catch2/catch.hpp>

#include "config_error.hpp"
#include "machine_config.hpp"
#include "test_machine.hpp"

using namespace hil;

namespace {

const std::string axes_yaml =
    "axes:\n  - {name: X, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}\n"
    "  - {name: Z, v_max: 100, a_max: 1000, j_max: 10000, kv: 40, velocity_lag_s: 0.002}\n";

MachineConfig machine(const std::string& channel_keys) {
  return parse_machine_config(YAML::Load(channel_keys + axes_yaml));
}

LiftMethod method(const std::string& preparation, const std::string& interpolator, int time_based) {
  return machine("path_preparation_function: \"" + preparation + "\"\ninterpolator_function: \"" + interpolator +
                 "\"\nenable_time_based_lift: " + std::to_string(time_based) + "\n")
      .lift_method;
}

void check_refused(const std::string& channel_keys, const std::string& part) {
  INFO(channel_keys);
  CHECK_THROWS_WITH(machine(channel_keys), Catch::Contains(part));
}

}  // namespace

TEST_CASE("LIFT-2 LIFT-3 LIFT-4 machine file: no lift function by default, lift_min_dist 0", "[config][lift]") {
  const MachineConfig m = machine("");
  CHECK(m.lift_method == LiftMethod::none);
  CHECK(m.lift_min_dist_mm == 0);
  CHECK(test::xyz_machine().lift_method == LiftMethod::none);
  CHECK(method("FCT_DEFAULT", "FCT_IPO_DEFAULT", 0) == LiftMethod::none);
}

TEST_CASE("LIFT-2 machine file: FCT_LIFT_UP_TIME in P-STUP-00060 and 00070 with P-CHAN-00345 = 1 is Advanced Lifting",
          "[config][lift]") {
  CHECK(method("FCT_DEFAULT | FCT_LIFT_UP_TIME", "FCT_IPO_DEFAULT | FCT_LIFT_UP_TIME", 1) == LiftMethod::time_based);
  // Blanks around '|' are free; the text's own example writes FCT_DEFAULT in P-STUP-00070.
  CHECK(method("FCT_LIFT_UP_TIME|FCT_DEFAULT", "FCT_DEFAULT|FCT_LIFT_UP_TIME", 1) == LiftMethod::time_based);
  CHECK(method("FCT_DEFAULT | FCT_LIFT_UP_TIME", "FCT_LOOK_AHEAD_STANDARD | FCT_LIFT_UP_TIME", 1) ==
        LiftMethod::time_based);
  const MachineConfig shipped = test::xyz_lift_machine();
  CHECK(shipped.lift_method == LiftMethod::time_based);
  CHECK(shipped.lift_min_dist_mm == 0);
  const AxisConfig& z = shipped.axes.at(static_cast<size_t>(shipped.axis_index("Z")));
  CHECK(z.dyn_monitoring_a_warn == 1900);
  CHECK(z.dyn_monitoring_a_err == 2000);
}

TEST_CASE("LIFT-3 machine file: FCT_LIFT_UP in P-STUP-00060 with P-CHAN-00345 = 0 is Lifting", "[config][lift]") {
  CHECK(method("FCT_DEFAULT | FCT_LIFT_UP", "FCT_IPO_DEFAULT", 0) == LiftMethod::path_based);
  CHECK(machine("path_preparation_function: FCT_DEFAULT | FCT_LIFT_UP\n").lift_method == LiftMethod::path_based);
  const MachineConfig shipped = test::xyz_lifting_machine();
  CHECK(shipped.lift_method == LiftMethod::path_based);
  const AxisConfig& z = shipped.axes.at(static_cast<size_t>(shipped.axis_index("Z")));
  CHECK(z.dyn_monitoring_a_warn == 1900);
  CHECK(z.dyn_monitoring_a_err == 2000);
}

TEST_CASE("LIFT-4 machine file: P-CHAN-00244 lift_min_dist is UNS32 in 0.1 um", "[config][lift]") {
  CHECK(machine("lift_min_dist: 50000\n").lift_min_dist_mm == Approx(5.0));
  CHECK(machine("lift_min_dist: 4294967295\n").lift_min_dist_mm == Approx(429496.7295));
  check_refused("lift_min_dist: -1\n", "machine.lift_min_dist");
  check_refused("lift_min_dist: 4294967296\n", "machine.lift_min_dist");
  check_refused("lift_min_dist: 1.5\n", "machine.lift_min_dist");
  check_refused("lift_min_dist: .nan\n", "machine.lift_min_dist");
}

TEST_CASE("LIFT-2 LIFT-3 machine file: contradictions of P-STUP-00060, 00070 and P-CHAN-00345 are refused",
          "[config][lift]") {
  // P-CHAN-00345 = 1 without FCT_LIFT_UP_TIME in both lists.
  check_refused("enable_time_based_lift: 1\n",
                "P-CHAN-00345 enable_time_based_lift = 1 needs FCT_LIFT_UP_TIME in both P-STUP-00060");
  check_refused("path_preparation_function: FCT_DEFAULT | FCT_LIFT_UP_TIME\nenable_time_based_lift: 1\n",
                "P-CHAN-00345 enable_time_based_lift = 1 needs FCT_LIFT_UP_TIME in both");
  check_refused("interpolator_function: FCT_IPO_DEFAULT | FCT_LIFT_UP_TIME\nenable_time_based_lift: 1\n",
                "P-CHAN-00345 enable_time_based_lift = 1 needs FCT_LIFT_UP_TIME in both");
  // FCT_LIFT_UP_TIME without P-CHAN-00345 = 1.
  check_refused(
      "path_preparation_function: FCT_DEFAULT | FCT_LIFT_UP_TIME\n"
      "interpolator_function: FCT_IPO_DEFAULT | FCT_LIFT_UP_TIME\n",
      "needs P-CHAN-00345 enable_time_based_lift = 1");
  check_refused("interpolator_function: FCT_IPO_DEFAULT | FCT_LIFT_UP_TIME\nenable_time_based_lift: 0\n",
                "needs P-CHAN-00345 enable_time_based_lift = 1");
  // FCT_LIFT_UP and FCT_LIFT_UP_TIME together.
  check_refused("path_preparation_function: FCT_DEFAULT | FCT_LIFT_UP | FCT_LIFT_UP_TIME\n"
                "interpolator_function: FCT_IPO_DEFAULT | FCT_LIFT_UP_TIME\nenable_time_based_lift: 1\n",
                "FCT_LIFT_UP (Lifting) and FCT_LIFT_UP_TIME (Advanced Lifting) exclude each other");
  check_refused("path_preparation_function: FCT_DEFAULT | FCT_LIFT_UP\n"
                "interpolator_function: FCT_IPO_DEFAULT | FCT_LIFT_UP_TIME\n",
                "exclude each other");
  // Lifting with P-CHAN-00345 = 1.
  check_refused("path_preparation_function: FCT_DEFAULT | FCT_LIFT_UP\nenable_time_based_lift: 1\n",
                "needs FCT_LIFT_UP_TIME in both");
  check_refused("enable_time_based_lift: 2\n", "machine.enable_time_based_lift");
}

TEST_CASE("LIFT-2 LIFT-3 machine file: identifiers of the function tables the rig does not have are refused by name",
          "[config][lift]") {
  for (const char* id : {"FCT_FFM", "FCT_PRESEGMENTATION", "FCT_SPLINE", "FCT_POLY", "FCT_CAX", "FCT_CAX_TRACK",
                         "FCT_SEGMENTATION", "FCT_EMF", "FCT_EMF_POLY_OFF", "FCT_SYNC", "FCT_PRECON", "FCT_PTP",
                         "FCT_M_PRE_OUTPUT", "FCT_SURFACE", "FCT_SEG_CHECK", "FCT_NIBBLING", "FCT_PUNCHING",
                         "FCT_VSM"})
    check_refused(std::string("path_preparation_function: FCT_DEFAULT | ") + id + "\n",
                  std::string("P-STUP-00060 path_preparation_function 'FCT_DEFAULT | ") + id + "': " + id +
                      " is not supported by this rig");
  for (const char* id : {"FCT_LOOK_AHEAD_LOW", "FCT_LOOK_AHEAD_HIGH", "FCT_LOOK_AHEAD_CUSTOM", "FCT_SYNC",
                         "FCT_LOOK_AHEAD_OPT", "FCT_SHIFT_NCBL", "FCT_CALC_STATE_AT_T", "FCT_CALC_TIME",
                         "FCT_CONTOUR_LAH", "FCT_DYN_POS_LIMIT", "FCT_EXTENSION_EQUIDIST", "FCT_CALC_POS_V_0",
                         "FCT_DLM"})
    check_refused(std::string("interpolator_function: FCT_IPO_DEFAULT | ") + id + "\n",
                  std::string("P-STUP-00070 interpolator_function 'FCT_IPO_DEFAULT | ") + id + "': " + id +
                      " is not supported by this rig");
}

TEST_CASE("LIFT-2 LIFT-3 machine file: unknown identifiers and malformed function lists are refused",
          "[config][lift]") {
  check_refused("path_preparation_function: FCT_DEFAULT | FCT_LIFT_UPTIME\n",
                "unknown identifier FCT_LIFT_UPTIME, did you mean FCT_LIFT_UP_TIME?");
  check_refused("path_preparation_function: FCT_DEFAULT | FOO_BAR_BAZ_QUX\n", "unknown identifier FOO_BAR_BAZ_QUX");
  // FCT_LIFT_UP is no identifier of the interpolator table, FCT_IPO_DEFAULT none of path preparation.
  check_refused("interpolator_function: FCT_IPO_DEFAULT | FCT_LIFT_UP\n",
                "P-STUP-00070 interpolator_function 'FCT_IPO_DEFAULT | FCT_LIFT_UP': unknown identifier FCT_LIFT_UP");
  check_refused("path_preparation_function: FCT_IPO_DEFAULT\n",
                "P-STUP-00060 path_preparation_function 'FCT_IPO_DEFAULT': unknown identifier FCT_IPO_DEFAULT");
  check_refused("path_preparation_function: FCT_DEFAULT || FCT_LIFT_UP\n", "an empty identifier");
  check_refused("path_preparation_function: \"\"\n", "an empty identifier");
  check_refused("path_preparation_function: FCT_DEFAULT | FCT_LIFT_UP | FCT_LIFT_UP\n", "FCT_LIFT_UP given twice");
  check_refused("path_preparation_function: FCT_LIFT_UP\n", "needs FCT_DEFAULT");
  check_refused("interpolator_function: FCT_LIFT_UP_TIME\n", "needs FCT_IPO_DEFAULT");
  check_refused("path_preparation_function: [FCT_DEFAULT]\n", "machine.path_preparation_function");
  check_refused("path_preparation: FCT_DEFAULT\n", "did you mean path_preparation_function?");
}
