#pragma once
// A 1-D motion made of segments of constant jerk (KRN-3). Evaluated in
// closed form at any time, so sampling it at the cycle time is exact.
#include <vector>

namespace hil::cnc {

struct MotionState {
  double p = 0;  // position
  double v = 0;  // velocity
  double a = 0;  // acceleration
  double j = 0;  // jerk of the segment the state lies in
};

struct JerkSegment {
  double duration = 0;  // s
  double jerk = 0;
};

class JerkProfile {
 public:
  JerkProfile() = default;
  JerkProfile(MotionState start, std::vector<JerkSegment> segments);

  double duration() const { return duration_; }
  // State at time t (clamped to [0, duration]).
  MotionState at(double t) const;
  const std::vector<JerkSegment>& segments() const { return segments_; }

 private:
  std::vector<JerkSegment> segments_;
  std::vector<MotionState> segment_start_;  // state at the start of each segment
  std::vector<double> segment_time_;        // start time of each segment
  MotionState start_;
  double duration_ = 0;
};

// State reached from `s` after time t at constant jerk j.
MotionState advance(const MotionState& s, double j, double t);

}  // namespace hil::cnc
