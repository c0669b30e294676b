#pragma once
// `same_path` (RIG-5, DPS-3): two runs of one program are on the same path
// if their commanded axis positions agree as a function of dist_prog_start,
// whatever the speed, holds or overrides. Block search proves itself this
// way: the searched run continues the uninterrupted run's path. No LCM.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hil::logger {

// One run's commanded path: a sample per cycle (the cycles both the HLI
// state and every axis' setpoint are logged for), in cycle order.
struct PathTrace {
  std::vector<std::string> axes;
  std::vector<double> modulo_range;  // per axis: > 0 on a modulo axis, else 0
  std::vector<int64_t> cycle;
  std::vector<double> dist_mm;                // HLI dist_prog_start, mm
  std::vector<std::vector<double>> position;  // [axis][sample]: the setpoint (AXIS_<X>_CMD), mm
};

struct SamePathResult {
  bool holds = false;
  int64_t compared = 0;  // samples of the variant compared on every axis
  int64_t skipped = 0;   // samples at an ambiguous reference distance
  int64_t not_finite = 0;  // NaN or infinite positions and distances (in either trace): the path fails
  // The largest difference of a compared sample (over all axes).
  struct Worst {
    int64_t cycle = 0;  // the variant's
    double dist_mm = 0;
    std::string axis;
    double variant_mm = 0, reference_mm = 0, difference_mm = 0;
  };
  std::optional<Worst> worst;
  double variant_end_mm = 0, reference_end_mm = 0;  // the largest dist_prog_start of each
  std::vector<std::string> failures;                // empty if it holds
};

// Every sample of `variant` beyond `from_dist_mm` against the reference's
// position at the same distance (linear between the reference's two samples
// around it, on the reference's forward motion). A distance at which the
// reference stood while an axis moved (#DISTANCE PROG START OFF) has no
// single position: such samples are skipped. On a modulo axis the
// difference is taken modulo its range. Axes are matched by name; an axis
// not in both traces is not compared.
SamePathResult compare_same_path(const PathTrace& reference, const PathTrace& variant, double from_dist_mm,
                                 double tolerance_mm);

// "N samples compared, M skipped, worst ... µm at ...", and why it fails.
std::string describe(const SamePathResult& result);

}  // namespace hil::logger
