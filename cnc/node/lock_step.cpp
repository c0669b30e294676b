#include "lock_step.hpp"

#include <algorithm>

namespace hil::cnc_node {

LockStep::Answerer LockStep::answerer(const std::string& name, const std::string& axis, const std::string& parameter,
                                      int64_t watchdog_cycles, const FaultPlan* faults) {
  Answerer a{name, axis, parameter, AnswerWatch(name, watchdog_cycles), std::nullopt, {}, false, 0};
  if (faults && faults->touches(name)) a.schedule.emplace(*faults, name);
  return a;
}

LockStep::LockStep(const MachineConfig& machine, bool watch_logger, int64_t answer_timeout_ms,
                   int64_t logger_timeout_ms, const FaultPlan* faults)
    : plc_(answerer("plc_sim", "", "plc_watchdog_cycles", machine.plc_watchdog_cycles, faults)),
      logger_(answerer("logger", "", "", 0, nullptr)), watch_logger_(watch_logger),
      answer_timeout_ms_(answer_timeout_ms), logger_timeout_ms_(logger_timeout_ms) {
  for (const AxisConfig& axis : machine.axes)
    axes_.push_back(answerer("axis_sim " + axis.name, axis.name, "watchdog_cycles", axis.watchdog_cycles, faults));
}

void LockStep::begin(int64_t cycle) {
  cycle_ = cycle;
  auto due = [cycle](Answerer& a) {
    a.errors = 0;
    a.awaited = a.schedule ? a.schedule->arrivals(cycle) : std::vector<int64_t>{cycle};
    if (a.lost) a.awaited.clear();
  };
  for (Answerer& a : axes_) due(a);
  due(plc_);
  control_.reset();
}

bool LockStep::take_due(Answerer& who, int64_t cycle, bool& use) {
  if (who.lost) return false;
  const auto it = std::find(who.awaited.begin(), who.awaited.end(), cycle);
  if (it == who.awaited.end()) return false;
  who.awaited.erase(it);
  const AnswerWatch::Answer a = who.watch.take(cycle, cycle_);
  use = a == AnswerWatch::Answer::in_time || a == AnswerWatch::Answer::late;
  return true;
}

bool LockStep::take_axis(size_t axis, int64_t cycle, int32_t errors) {
  Answerer& a = axes_.at(axis);
  bool use = false;
  if (!take_due(a, cycle, use)) return false;
  if (use) a.errors |= errors;  // an error in any answer of the cycle reaches the channel
  return true;
}

bool LockStep::take_plc(int64_t cycle, const HliControl& control) {
  bool use = false;
  if (!take_due(plc_, cycle, use)) return false;
  if (use) control_ = control;  // the newest: answers are taken in order
  return true;
}

bool LockStep::complete() const {
  if (!plc_.lost && !plc_.awaited.empty()) return false;
  for (const Answerer& a : axes_)
    if (!a.lost && !a.awaited.empty()) return false;
  return true;
}

void LockStep::lose(Answerer& who, const std::string& what, const std::string& parameter) {
  who.lost = true;
  who.errors = 0;
  who.awaited.clear();
  newly_lost_.push_back({who.name, who.axis, what, parameter});
  lost_so_far_.emplace_back(who.name, cycle_);
}

std::vector<std::string> LockStep::lose_silent(const Liveness& liveness) {
  std::vector<std::string> waited_for;
  auto silent = [&](Answerer& a) {
    if (a.awaited.empty() || a.lost) return;
    const ProcessState process = liveness ? liveness(a.name) : ProcessState::unknown;
    if (process == ProcessState::running) return waited_for.push_back(a.name);
    lose(a, "no answer to cycle " + std::to_string(cycle_) + " within " + std::to_string(answer_timeout_ms_) + " ms");
  };
  for (Answerer& a : axes_) silent(a);
  silent(plc_);
  return waited_for;
}

bool LockStep::check_logger(int64_t now_us, const Liveness& liveness) {
  if (!watch_logger_ || logger_.lost) return false;
  const int64_t timeout_us = logger_timeout_ms_ * 1000;
  if (!logger_behind()) logger_behind_since_us_ = -1;
  else if (logger_behind_since_us_ < 0) logger_behind_since_us_ = now_us;
  const bool silent = now_us - logger_heard_us_ > timeout_us;
  const bool behind = logger_behind_since_us_ >= 0 && now_us - logger_behind_since_us_ > timeout_us;
  if (!silent && !behind) return false;
  if (liveness && liveness(logger_.name) == ProcessState::running) return true;  // a loaded host: waited for
  if (silent)
    lose(logger_, "no heartbeat for " + std::to_string((now_us - logger_heard_us_) / 1000) + " ms at cycle " +
                      std::to_string(cycle_) + ": the run is no longer recorded");
  else
    lose(logger_, "it has recorded up to cycle " + std::to_string(logger_cycle_) + " and not caught up with cycle " +
                      std::to_string(cycle_) + " within " + std::to_string(logger_timeout_ms_) +
                      " ms: the run is no longer recorded");
  return false;
}

LockStep::Taken LockStep::take() {
  auto watchdog = [this](Answerer& a) {
    // Without faults planned on it every answer is due in its own cycle
    // and waited for (the wall-clock timeout loses a silent one).
    if (a.lost || !a.schedule || !a.watch.end_cycle(cycle_)) return;
    lose(a,
         "watchdog: no answer for " + std::to_string(a.watch.silent_cycles()) + " cycles (" +
             a.watchdog_parameter + " " + std::to_string(a.watch.watchdog_cycles()) + ")",
         a.watchdog_parameter);
  };
  for (Answerer& a : axes_) watchdog(a);
  watchdog(plc_);
  Taken t;
  t.control = control_;
  for (const Answerer& a : axes_) t.axis_errors.push_back(a.lost ? 0 : a.errors);
  t.lost.swap(newly_lost_);
  return t;
}

std::vector<std::pair<std::string, AnswerCounts>> LockStep::answer_counts() const {
  std::vector<std::pair<std::string, AnswerCounts>> out;
  for (const Answerer& a : axes_) out.emplace_back(a.name, a.watch.counts());
  out.emplace_back(plc_.name, plc_.watch.counts());
  return out;
}

}  // namespace hil::cnc_node
