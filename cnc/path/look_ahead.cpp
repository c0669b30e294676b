#include "look_ahead.hpp"

#include <algorithm>
#include <limits>

#include "bisect.hpp"
#include "corner_rule.hpp"
#include "velocity_profile.hpp"

namespace hil::cnc {

double highest_entry_velocity(double v_exit, double distance, double v_cap, const Limits& lim, SlopeType slope) {
  if (v_cap <= v_exit) return v_cap;
  auto covers = [&](double v0) { return velocity_change(v0, 0, v_exit, lim, slope).end({0, v0, 0, 0}).p; };
  if (covers(v_cap) <= distance) return v_cap;
  // v_exit fits, v_cap does not; the distance grows with v0.
  return last_fitting(v_exit, v_cap, [&](double v0) { return covers(v0) <= distance; });
}

LookAhead::LookAhead(const MachineConfig& machine, size_t capacity) : machine_(machine), capacity_(capacity) {}

void LookAhead::push(size_t block_index, PathSegment segment, SlopeType slope, bool stop_before) {
  double jerk_share = 1;
  if (!blocks_.empty()) {
    const Junction j = junction(blocks_.back().segment, segment, machine_);
    blocks_.back().junction_limit = stop_before ? 0.0 : j.v_max;
    if (j.curvature_step) blocks_.back().jerk_share = jerk_share = curvature_step_jerk_share;
  }
  blocks_.push_back({block_index, std::move(segment), slope, 0.0, jerk_share, 0.0, true});
  backward_pass(blocks_.size() - 1, true);
}

void LookAhead::set_velocity_factor(double factor) {
  if (factor == factor_) return;
  factor_ = factor;
  if (!blocks_.empty()) backward_pass(blocks_.size() - 1, false);
}

Limits LookAhead::cruise_limits(size_t i) const {
  const PathSegment& seg = blocks_[i].segment;
  Limits lim = seg.limits();
  lim.v = std::min(lim.v, factor_ * seg.programmed_velocity());
  lim.j *= blocks_[i].jerk_share;
  return lim;
}

Stretch LookAhead::stretch(double v_now) const {
  Stretch st{0, 0, cruise_limits(0), blocks_.front().slope};
  for (size_t i = 0; i < blocks_.size(); ++i) {
    const Limits lim = cruise_limits(i);
    st.lim.a = std::min(st.lim.a, lim.a);
    st.lim.j = std::min(st.lim.j, lim.j);
    st.length += blocks_[i].segment.length();
    st.v_end = blocks_[i].v_end;
    if (blocks_[i].limiting || blocks_[i].v_end < v_now) break;
  }
  return st;
}

void LookAhead::backward_pass(size_t last, bool until_unchanged) {
  blocks_[last].v_end = 0;  // nothing known beyond it: it must be able to stop
  blocks_[last].limiting = true;
  double v_next = 0, distance = 0;  // of the next limiting transition
  Limits lim{0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (size_t i = last; i-- > 0;) {
    const LookAheadBlock& next = blocks_[i + 1];
    const Limits next_lim = cruise_limits(i + 1);
    distance += next.segment.length();
    lim = {next_lim.v, std::min(lim.a, next_lim.a), std::min(lim.j, next_lim.j)};
    LookAheadBlock& b = blocks_[i];
    const double cruise = cruise_limits(i).v;
    const double cap = std::min({b.junction_limit, cruise, next_lim.v});
    b.limiting = cap < std::max(cruise, next_lim.v) || b.slope != next.slope;
    if (!b.limiting) {
      b.v_end = cap;  // the path passes at cruise velocity or below
      continue;
    }
    const double v = highest_entry_velocity(v_next, distance, cap, lim, next.slope);
    if (until_unchanged && v == b.v_end) break;
    b.v_end = v_next = v;
    distance = 0;
    lim.a = lim.j = std::numeric_limits<double>::infinity();
  }
}

}  // namespace hil::cnc
