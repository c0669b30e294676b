#include "same_path.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hil::logger {
namespace {

std::string num(double v, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// a - b; on a modulo axis the shortest way round (359.9999 and 0 are 0.0001 apart).
double difference(double a, double b, double modulo_range) {
  const double d = a - b;
  return modulo_range > 0 ? std::remainder(d, modulo_range) : d;
}

// The reference's forward motion: the samples at which dist_prog_start
// reaches or passes the largest so far (backward travel and the way back to
// where it turned are left out), grouped by equal distance. A group of
// several samples is a standstill or a section without counting
// (#DISTANCE PROG START OFF); it is ambiguous if an axis moved within it.
struct Run {
  double dist = 0;
  size_t first = 0, last = 0;  // sample indices
  bool ambiguous = false;
};

std::vector<Run> forward_runs(const PathTrace& t, double tolerance_mm) {
  std::vector<Run> runs;
  for (size_t i = 0; i < t.dist_mm.size(); ++i) {
    const double d = t.dist_mm[i];
    if (!std::isfinite(d)) continue;  // no distance: counted as not finite by the caller
    if (!runs.empty() && d < runs.back().dist) continue;
    if (!runs.empty() && d == runs.back().dist) {
      Run& r = runs.back();
      r.last = i;
      for (size_t a = 0; a < t.axes.size(); ++a)
        if (std::abs(difference(t.position[a][i], t.position[a][r.first], t.modulo_range[a])) > tolerance_mm)
          r.ambiguous = true;
      continue;
    }
    runs.push_back({d, i, i, false});
  }
  return runs;
}

}  // namespace

SamePathResult compare_same_path(const PathTrace& reference, const PathTrace& variant, double from_dist_mm,
                                 double tolerance_mm) {
  SamePathResult r;
  // variant axis -> reference axis
  std::vector<std::pair<size_t, size_t>> axes;
  for (size_t a = 0; a < variant.axes.size(); ++a)
    for (size_t b = 0; b < reference.axes.size(); ++b)
      if (variant.axes[a] == reference.axes[b]) axes.push_back({a, b});
  const std::vector<Run> runs = forward_runs(reference, tolerance_mm);
  for (double d : reference.dist_mm) r.reference_end_mm = std::max(r.reference_end_mm, d);
  for (double d : variant.dist_mm) r.variant_end_mm = std::max(r.variant_end_mm, d);
  for (double d : reference.dist_mm) r.not_finite += std::isfinite(d) ? 0 : 1;
  for (const auto& positions : reference.position)
    for (double p : positions) r.not_finite += std::isfinite(p) ? 0 : 1;

  int64_t beyond = 0, before = 0;
  std::optional<double> first_beyond;
  for (size_t i = 0; i < variant.dist_mm.size(); ++i) {
    const double d = variant.dist_mm[i];
    if (!std::isfinite(d)) {
      ++r.not_finite;
      continue;
    }
    if (!(d > from_dist_mm)) continue;
    const auto k = std::lower_bound(runs.begin(), runs.end(), d, [](const Run& run, double v) { return run.dist < v; });
    // The reference's position at d: at sample `at`, or between `at` and `next` (by `f`).
    size_t at = 0, next = 0;
    double f = 0;
    if (k != runs.end() && k->dist == d) {
      if (k->ambiguous) {
        ++r.skipped;
        continue;
      }
      at = next = k->last;
    } else if (k == runs.begin()) {
      ++before;  // below the reference's first distance: it has no position there
      continue;
    } else if (k == runs.end()) {
      if (d - runs.back().dist > tolerance_mm) {
        if (!first_beyond) first_beyond = d;
        ++beyond;
        continue;
      }
      at = next = runs.back().last;
    } else {
      const Run& lo = *(k - 1);
      at = lo.last;
      next = k->first;
      f = (d - lo.dist) / (k->dist - lo.dist);
    }
    for (const auto& [va, ra] : axes) {
      const double p0 = reference.position[ra][at], p1 = reference.position[ra][next];
      const double ref = p0 + (p1 - p0) * f;
      const double diff = difference(variant.position[va][i], ref, reference.modulo_range[ra]);
      if (!std::isfinite(diff)) {  // never the worst: NaN compares false with every tolerance
        ++r.not_finite;
        continue;
      }
      if (!r.worst || std::abs(diff) > std::abs(r.worst->difference_mm))
        r.worst = SamePathResult::Worst{variant.cycle[i], d, variant.axes[va], variant.position[va][i], ref, diff};
    }
    ++r.compared;
  }

  if (r.worst && std::abs(r.worst->difference_mm) > tolerance_mm)
    r.failures.push_back("a sample differs by more than " + num(tolerance_mm * 1000, 3) + " µm");
  if (r.compared == 0) r.failures.push_back("no sample was compared");
  if (r.not_finite > 0)
    r.failures.push_back(std::to_string(r.not_finite) + " position(s) or distance(s) not a finite number");
  if (r.variant_end_mm < r.reference_end_mm - tolerance_mm)
    r.failures.push_back("the variant ended at dist_prog_start " + num(r.variant_end_mm, 4) + " mm, the reference at " +
                         num(r.reference_end_mm, 4) + " mm: it did not run to the end");
  if (beyond > 0)
    r.failures.push_back(std::to_string(beyond) + " sample(s) beyond the reference's end (" +
                         num(r.reference_end_mm, 4) + " mm), the first at " + num(*first_beyond, 4) + " mm");
  if (before > 0)
    r.failures.push_back(std::to_string(before) + " sample(s) before the reference's first distance: not compared");
  r.holds = r.failures.empty();
  return r;
}

std::string describe(const SamePathResult& r) {
  std::string s = std::to_string(r.compared) + " samples compared, " + std::to_string(r.skipped) + " skipped";
  if (r.worst) {
    const SamePathResult::Worst& w = *r.worst;
    s += ", worst difference " + num(std::abs(w.difference_mm) * 1000, 3) + " µm (cycle " + std::to_string(w.cycle) +
         ", dist_prog_start " + num(w.dist_mm, 4) + " mm, " + w.axis + ": " + num(w.variant_mm, 6) + " mm vs reference " +
         num(w.reference_mm, 6) + " mm)";
  }
  s += "; ends at " + num(r.variant_end_mm, 4) + " / " + num(r.reference_end_mm, 4) + " mm";
  for (const std::string& f : r.failures) s += "; " + f;
  return s;
}

}  // namespace hil::logger
