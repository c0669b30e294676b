#include "lock_step.hpp"

namespace hil::cnc_node {

LockStep::LockStep(const MachineConfig& machine, bool watch_logger, int64_t answer_timeout_ms,
                   int64_t logger_timeout_ms)
    : watch_logger_(watch_logger), answer_timeout_ms_(answer_timeout_ms), logger_timeout_ms_(logger_timeout_ms) {
  for (const AxisConfig& axis : machine.axes) axes_.push_back({"axis_sim " + axis.name, axis.name});
}

void LockStep::begin(int64_t cycle) {
  cycle_ = cycle;
  for (Answerer& a : axes_) a.answered = false;
  plc_.answered = false;
  control_.reset();
}

bool LockStep::take_axis(size_t axis, int64_t cycle, int32_t errors) {
  Answerer& a = axes_.at(axis);
  if (cycle != cycle_ || a.answered || a.lost) return false;
  a.answered = true;
  a.errors = errors;
  return true;
}

bool LockStep::take_plc(int64_t cycle, const HliControl& control) {
  if (cycle != cycle_ || plc_.answered || plc_.lost) return false;
  plc_.answered = true;
  control_ = control;
  return true;
}

bool LockStep::complete() const {
  if (!plc_.answered && !plc_.lost) return false;
  for (const Answerer& a : axes_)
    if (!a.answered && !a.lost) return false;
  return true;
}

void LockStep::lose(Answerer& who, const std::string& what) {
  who.lost = true;
  who.errors = 0;
  newly_lost_.push_back({who.name, who.axis, what});
  lost_so_far_.emplace_back(who.name, cycle_);
}

void LockStep::lose_silent() {
  const std::string what =
      "no answer to cycle " + std::to_string(cycle_) + " within " + std::to_string(answer_timeout_ms_) + " ms";
  for (Answerer& a : axes_)
    if (!a.answered && !a.lost) lose(a, what);
  if (!plc_.answered && !plc_.lost) lose(plc_, what);
}

void LockStep::check_logger(int64_t now_us) {
  if (!watch_logger_ || logger_.lost) return;
  const int64_t timeout_us = logger_timeout_ms_ * 1000;
  if (now_us - logger_heard_us_ > timeout_us)
    return lose(logger_, "no heartbeat for " + std::to_string((now_us - logger_heard_us_) / 1000) + " ms at cycle " +
                             std::to_string(cycle_) + ": the run is no longer recorded");
  if (!logger_behind()) {
    logger_behind_since_us_ = -1;
    return;
  }
  if (logger_behind_since_us_ < 0) logger_behind_since_us_ = now_us;
  if (now_us - logger_behind_since_us_ > timeout_us)
    lose(logger_, "it has recorded up to cycle " + std::to_string(logger_cycle_) + " and not caught up with cycle " +
                      std::to_string(cycle_) + " within " + std::to_string(logger_timeout_ms_) +
                      " ms: the run is no longer recorded");
}

LockStep::Taken LockStep::take() {
  Taken t;
  t.control = control_;
  for (const Answerer& a : axes_) t.axis_errors.push_back(a.lost ? 0 : a.errors);
  t.lost.swap(newly_lost_);
  return t;
}

}  // namespace hil::cnc_node
