#include "jerk_profile.hpp"

#include <algorithm>

namespace hil::cnc {

MotionState advance(const MotionState& s, double j, double t) {
  MotionState r;
  r.p = s.p + t * (s.v + t * (s.a / 2 + t * j / 6));
  r.v = s.v + t * (s.a + t * j / 2);
  r.a = s.a + t * j;
  r.j = j;
  return r;
}

JerkProfile::JerkProfile(MotionState start, std::vector<JerkSegment> segments)
    : segments_(std::move(segments)), start_(start) {
  MotionState state = start;
  double time = 0;
  for (const JerkSegment& seg : segments_) {
    segment_start_.push_back(state);
    segment_time_.push_back(time);
    state = advance(state, seg.jerk, seg.duration);
    time += seg.duration;
  }
  duration_ = time;
}

MotionState JerkProfile::at(double t) const {
  if (segments_.empty()) return start_;
  t = std::clamp(t, 0.0, duration_);
  // Last segment whose start time is <= t.
  const auto it = std::upper_bound(segment_time_.begin(), segment_time_.end(), t);
  const size_t i = static_cast<size_t>(std::max<std::ptrdiff_t>(0, (it - segment_time_.begin()) - 1));
  MotionState state = advance(segment_start_[i], segments_[i].jerk, t - segment_time_[i]);
  if (t >= duration_) state.j = 0;
  return state;
}

}  // namespace hil::cnc
