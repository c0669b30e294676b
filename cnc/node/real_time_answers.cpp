#include "real_time_answers.hpp"

namespace hil::cnc_node {

RealTimeAnswers::RealTimeAnswers(const MachineConfig& machine, bool watch_logger, int64_t logger_timeout_ms)
    : watch_logger_(watch_logger), logger_timeout_ms_(logger_timeout_ms) {
  for (const AxisConfig& axis : machine.axes) {
    watches_.emplace_back("axis_sim " + axis.name, axis.watchdog_cycles);
    axes_.push_back(axis.name);
  }
  watches_.emplace_back("plc_sim", machine.plc_watchdog_cycles);
  axes_.emplace_back();
  lost_.assign(watches_.size(), false);
  errors_.assign(machine.axes.size(), 0);
}

bool RealTimeAnswers::take(size_t who, int64_t cycle) {
  const AnswerWatch::Answer a = watches_.at(who).take(cycle, cycle_);
  return a == AnswerWatch::Answer::in_time || a == AnswerWatch::Answer::late;
}

bool RealTimeAnswers::take_axis(size_t axis, int64_t cycle, int32_t errors) {
  if (axis >= errors_.size() || cycle > cycle_) return false;
  if (take(axis, cycle)) errors_[axis] |= errors;  // a monitoring error in any answer is one
  return true;
}

bool RealTimeAnswers::take_plc(int64_t cycle, const HliControl& control) {
  if (cycle > cycle_) return false;
  if (take(watches_.size() - 1, cycle)) control_ = control;
  return true;
}

RealTimeAnswers::Taken RealTimeAnswers::end_cycle(int64_t now_us, bool overrun) {
  Taken t;
  t.control.swap(control_);
  t.axis_errors.swap(errors_);
  errors_.assign(t.axis_errors.size(), 0);
  for (size_t i = 0; i < watches_.size(); ++i) {
    AnswerWatch& w = watches_[i];
    if (!w.end_cycle(cycle_, !overrun) || lost_[i]) continue;
    lost_[i] = true;
    const std::string parameter = axes_[i].empty() ? "plc_watchdog_cycles" : "watchdog_cycles";
    const int64_t not_counted = w.cycles_since_heard(cycle_) - w.silent_cycles();
    t.lost.push_back({w.name(), axes_[i],
                      "watchdog: no answer for " + std::to_string(w.silent_cycles()) + " cycles (" + parameter + " " +
                          std::to_string(w.watchdog_cycles()) + ")" +
                          (not_counted > 0 ? ", " + std::to_string(not_counted) +
                                                 " more the CNC ran late (overruns) not counted"
                                           : ""),
                      parameter});
    lost_so_far_.emplace_back(w.name(), cycle_);
  }
  if (watch_logger_ && !logger_lost_ && now_us - logger_heard_us_ > logger_timeout_ms_ * 1000) {
    logger_lost_ = true;
    t.lost.push_back({"logger", "",
                      "no heartbeat for " + std::to_string((now_us - logger_heard_us_) / 1000) + " ms at cycle " +
                          std::to_string(cycle_) + ": the run is no longer recorded",
                      ""});
    lost_so_far_.emplace_back("logger", cycle_);
  }
  return t;
}

}  // namespace hil::cnc_node
