#pragma once
// A 1-D motion as a sequence of phases in which the acceleration moves
// monotonically from one value to another (KRN-3). Each phase is a piece of
// a linear ramp (constant jerk: TRAPEZ, or a STEP jump of zero duration) or
// of a sin² ramp (SIN2). Evaluated in closed form at any time, so sampling
// it at the cycle time is exact.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <new>
#include <stdexcept>
#include <type_traits>

namespace hil::cnc {

struct MotionState {
  double p = 0;  // position
  double v = 0;  // velocity
  double a = 0;  // acceleration
  double j = 0;  // jerk at this instant (0 across a STEP jump)
};

struct Phase {
  enum class Shape { linear, sin2 };
  double duration = 0;  // 0 with a_end != start acceleration: a STEP jump
  double a_end = 0;     // acceleration at the end of the phase
  Shape shape = Shape::linear;
  double jerk = 0;  // linear only; kept exact, not derived from tiny differences
  // sin2 only: the phase is the part [u0, u0 + duration/ramp_time] of a
  // whole ramp a(u) = base + ramp_delta_a * (u - sin(2 pi u) / 2 pi).
  double ramp_time = 0;
  double ramp_delta_a = 0;
  double u0 = 0;
};

// State after `tau` (0 <= tau <= phase.duration) into `phase` begun in `s`.
// Inline: the planners' searches evaluate it thousands of times a second.
MotionState advance_sin2(const MotionState& s, const Phase& phase, double tau);
inline MotionState advance(const MotionState& s, const Phase& ph, double tau) {
  if (ph.shape == Phase::Shape::sin2 && ph.ramp_time > 0) return advance_sin2(s, ph, tau);
  MotionState r;
  if (!(ph.duration > 0)) {  // a STEP jump, or nothing
    r = s;
    r.a = ph.a_end;
    r.j = 0;
    return r;
  }
  const double j = ph.jerk;
  r.p = s.p + tau * (s.v + tau * (s.a / 2 + tau * j / 6));
  r.v = s.v + tau * (s.a + tau * j / 2);
  r.a = tau >= ph.duration ? ph.a_end : s.a + tau * j;
  r.j = j;
  return r;
}

// Builders of the phases the planners use.
inline Phase hold(double duration, double a) {  // constant acceleration
  Phase ph;
  ph.duration = duration;
  ph.a_end = a;
  return ph;
}
inline Phase linear_ramp(double a_from, double a_to, double jerk) {  // jerk > 0, or infinite for a jump
  Phase ph;
  ph.duration = std::isinf(jerk) ? 0.0 : std::abs(a_to - a_from) / jerk;
  ph.jerk = ph.duration > 0 ? std::copysign(jerk, a_to - a_from) : 0.0;
  ph.a_end = a_to;
  return ph;
}
Phase sin2_ramp(double a_from, double a_to, double peak_jerk);

// Up to N values held in place: a plan allocates nothing (the planners
// replan every cycle), and slots beyond size() are never written.
template <typename T, std::size_t N>
class InlineList {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  static constexpr std::size_t capacity = N;
  InlineList() {}  // NOLINT: the storage stays unwritten on purpose
  InlineList(const InlineList& other) { *this = other; }
  InlineList& operator=(const InlineList& other) {
    if (this == &other) return *this;
    size_ = other.size_;
    std::memcpy(storage_, other.storage_, size_ * sizeof(T));  // trivially copyable: one copy, not size_ pushes
    return *this;
  }
  // Throws std::length_error beyond capacity (no planner gets there).
  void push_back(const T& x) {
    if (size_ == N) throw std::length_error("InlineList: capacity exceeded");
    new (storage_ + size_ * sizeof(T)) T(x);
    ++size_;
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const T* begin() const { return std::launder(reinterpret_cast<const T*>(storage_)); }
  const T* end() const { return begin() + size_; }
  const T& operator[](std::size_t i) const { return begin()[i]; }

 private:
  alignas(T) unsigned char storage_[N * sizeof(T)];
  std::size_t size_ = 0;
};

// The phases of a profile. The most any planner builds is 9: a velocity
// change of up to 4 phases, a cruise, and another of up to 4.
using PhaseList = InlineList<Phase, 9>;

class MotionProfile {
 public:
  MotionProfile() = default;
  MotionProfile(MotionState start, const PhaseList& phases);

  double duration() const { return duration_; }
  MotionState start() const { return start_; }
  MotionState end() const { return end_; }
  // State at time t: before 0 the start; after duration() the motion goes
  // on at the end velocity (every planner's profile ends with a = 0), and a
  // stop (its end velocity 0 to round-off) stays where it ended. A path
  // whose plan ended on a block transition it crosses moving, replanned in
  // the next cycle, goes on from where it then is; taken from where the
  // plan ended it stood still for the rest of the cycle (KRN-3: 1.66e6
  // mm/s^3 when an override change came in that cycle).
  MotionState at(double t) const;
  const PhaseList& phases() const { return phases_; }
  // State at the start of phase i (i == phases().size(): the end).
  MotionState phase_start(std::size_t i) const { return i < starts_.size() ? starts_[i] : end_; }
  double phase_start_time(std::size_t i) const { return i < times_.size() ? times_[i] : duration_; }

 private:
  PhaseList phases_;
  InlineList<MotionState, PhaseList::capacity> starts_;
  InlineList<double, PhaseList::capacity> times_;
  MotionState start_, end_;
  double duration_ = 0;
  bool moving_at_end_ = false;  // not a stop (whose end velocity is 0 to round-off)
};

}  // namespace hil::cnc
