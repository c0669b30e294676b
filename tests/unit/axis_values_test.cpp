// issue 17: one value per machine axis without an allocation up to 8 axes
// (AxisValues), and a machine with more axes than that decoded and planned
// as before (KRN-1, KRN-3).
#include <catch2/catch.hpp>

#include <vector>

#include "axis_values.hpp"
#include "decoder.hpp"
#include "path_segment.hpp"
#include "test_machine.hpp"

using hil::AxisValues;

TEST_CASE("AxisValues: inline up to 8 axes, on the heap beyond, a vector's behaviour either way", "[issue17]") {
  for (size_t n : {0u, 1u, 3u, 8u, 9u, 20u}) {
    std::vector<double> reference;
    AxisValues values;
    for (size_t i = 0; i < n; ++i) {
      reference.push_back(1.5 * static_cast<double>(i) - 2);
      values.push_back(reference.back());
    }
    REQUIRE(values.size() == n);
    REQUIRE(std::vector<double>(values) == reference);
    REQUIRE(AxisValues(reference) == values);

    AxisValues copy = values;
    REQUIRE(copy == values);
    AxisValues moved = std::move(copy);
    REQUIRE(moved == values);
    REQUIRE(copy.empty());  // NOLINT: left empty on purpose

    // Assignments across the inline/heap boundary both ways.
    AxisValues small{1, 2, 3};
    small = values;
    REQUIRE(small == values);
    AxisValues large(12, 7.0);
    large = values;
    REQUIRE(large == values);
    AxisValues large_moved(12, 7.0);
    large_moved = std::move(moved);
    REQUIRE(large_moved == values);

    AxisValues resized = values;
    resized.resize(n + 10, 4.0);
    REQUIRE(resized.size() == n + 10);
    for (size_t i = 0; i < n; ++i) REQUIRE(resized[i] == reference[i]);
    for (size_t i = n; i < n + 10; ++i) REQUIRE(resized[i] == 4.0);
    resized.resize(n);
    REQUIRE(resized == values);
    if (n > 0) REQUIRE(resized != AxisValues(n, 99.0));
  }
}

TEST_CASE("KRN-1 KRN-3: a machine with 9 axes (more than AxisValues holds inline) decodes and plans its moves",
          "[issue17][decoder]") {
  hil::MachineConfig machine = hil::test::xyz_machine();
  const hil::AxisConfig x = machine.axes[0];
  machine.axes.clear();
  for (const char* name : {"X", "Y", "Z", "A", "B", "C", "U", "V", "W"}) {
    hil::AxisConfig axis = x;
    axis.name = name;
    machine.axes.push_back(axis);
  }
  const auto program = hil::cnc::decode_program(
      "N10 G01 X1 Y2 Z3 A4 B5 C6 U7 V8 W9 F6000\nN20 G91 W1 X-1\nM30\n", machine, std::vector<double>(9, 0.0));
  REQUIRE_FALSE(program.error);
  REQUIRE(program.blocks.size() >= 2);
  const hil::cnc::Motion& first = program.blocks[0].motion;
  const hil::cnc::Motion& second = program.blocks[1].motion;
  REQUIRE(first.start == AxisValues(9, 0.0));
  REQUIRE(first.end == AxisValues{1, 2, 3, 4, 5, 6, 7, 8, 9});
  REQUIRE(second.start == first.end);
  REQUIRE(second.end == AxisValues{0, 2, 3, 4, 5, 6, 7, 8, 10});

  const hil::cnc::PathSegment segment(second, machine);
  REQUIRE(segment.length() == Approx(std::sqrt(2.0)));
  REQUIRE(segment.end() == second.end);
}
