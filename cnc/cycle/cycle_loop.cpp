#include "cycle_loop.hpp"

#include "run_end.hpp"

namespace hil::cnc {
namespace {

Event lost_event(const LostParticipant& p) {
  Event e;
  e.axis = p.axis;
  e.parameter = p.parameter;
  e.message = p.name + " lost: " + p.what + "; the run goes on without it";
  return e;
}

}  // namespace

CycleLoopResult run_cycles(Channel& channel, const Scenario& scenario, CyclePolicy& policy) {
  RunEnd run_end(scenario);
  HliControl control;  // the PLC's answer to the previous cycle
  for (int64_t k = 0;; ++k) {
    channel.step(k, control);
    if (!policy.publish(k, channel, channel.take_events())) return {RunOutcome::publish_refused, k};
    const std::optional<CycleAnswers> answers = policy.answers(k);
    if (!answers) return {RunOutcome::answers_missing, k};
    if (answers->control) control = *answers->control;
    for (const DriveError& e : answers->drive_errors) channel.drive_error(e.axis, e.what);
    for (const LostParticipant& p : answers->lost) {
      if (!policy.publish_event(k, lost_event(p))) return {RunOutcome::publish_refused, k};
      if (p.axis.empty()) channel.error_stop(p.name + " lost (" + p.what + ")");
      else channel.drive_error(p.axis, p.name + " lost: " + p.what);
    }
    if (run_end.settled(channel, k)) return {RunOutcome::settled, k};
    if (run_end.timed_out(k)) {
      if (!policy.publish_event(k, run_end.timeout_event())) return {RunOutcome::publish_refused, k};
      return {RunOutcome::timed_out, k};
    }
  }
}

}  // namespace hil::cnc
