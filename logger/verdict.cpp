#include "verdict.hpp"

#include <algorithm>

#include "channels.hpp"

namespace hil::logger {
namespace {

std::string list(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

// Each cycle 0 .. last once on a lock-step channel. Counted on the sorted
// cycles the log holds, never on a table of cycles 0 .. last: `last` is what
// a RUN_END says, and a forged one may say 10^12.
void check_cycles(const std::string& channel, const std::vector<int64_t>& cycles, int64_t last,
                  std::vector<std::string>& problems) {
  std::vector<int64_t> in_range;
  int64_t wrong = 0;
  for (const int64_t c : cycles)
    if (c < 0 || c > last) ++wrong;
    else in_range.push_back(c);
  std::sort(in_range.begin(), in_range.end());
  int64_t distinct = 0, first_missing = -1;
  for (size_t i = 0; i < in_range.size(); ++i) {
    if (i > 0 && in_range[i] == in_range[i - 1]) {
      ++wrong;
      continue;
    }
    if (first_missing < 0 && in_range[i] != distinct) first_missing = distinct;
    ++distinct;
  }
  const int64_t missing = last + 1 - distinct;
  if (missing > 0 && first_missing < 0) first_missing = distinct;
  if (missing > 0)
    problems.push_back(channel + ": " + std::to_string(missing) + " of " + std::to_string(last + 1) +
                       " cycles missing (the first: " + std::to_string(first_missing) + ")");
  if (wrong > 0)
    problems.push_back(channel + ": " + std::to_string(wrong) + " message(s) of a wrong cycle (repeated, or outside 0.." +
                       std::to_string(last) + ")");
}

// The most cycles the log can show: the most messages on one lock-step channel.
int64_t cycles_held(const LogFacts& f) {
  size_t most = 0;
  for (const auto& entry : f.lock_step) most = std::max(most, entry.second.size());
  return static_cast<int64_t>(most);
}

// Room for the cycles planned faults take out of every lock-step channel
// at once; beyond it a RUN_END's cycle is not the run's (and checking the
// planned copies of each cycle up to it would take as long as it says).
int64_t plausible_last_cycle(int64_t held) { return 2 * held + 1000; }

// How often the log must hold each cycle 0 .. last of a channel the faults
// act on: the senders' rules replayed (fault_plan.hpp).
std::vector<int> expected_copies(const FaultPlan& plan, const std::string& channel, int64_t last) {
  std::vector<int> copies(static_cast<size_t>(last + 1), 0);
  const std::string sender = sender_of(channel);
  if (sender == "cnc") {
    for (int64_t k = 0; k <= last; ++k) copies[static_cast<size_t>(k)] = plan.fate(channel, k).copies();
    return copies;
  }
  AnswerSchedule schedule(plan, sender);
  for (int64_t j = 0; j <= last; ++j)
    for (const int64_t k : schedule.arrivals(j)) ++copies[static_cast<size_t>(k)];
  return copies;
}

void check_planned_cycles(const std::string& channel, const std::vector<int64_t>& cycles, int64_t last,
                          const FaultPlan& plan, std::vector<std::string>& problems) {
  const std::vector<int> expected = expected_copies(plan, channel, last);
  std::vector<int> seen(expected.size(), 0);
  int64_t outside = 0, differ = 0, first = -1;
  for (const int64_t c : cycles)
    if (c < 0 || c > last) ++outside;
    else ++seen[static_cast<size_t>(c)];
  for (size_t c = 0; c < expected.size(); ++c)
    if (seen[c] != expected[c]) {
      if (first < 0) first = static_cast<int64_t>(c);
      ++differ;
    }
  if (differ > 0)
    problems.push_back(channel + ": " + std::to_string(differ) + " cycle(s) not as the planned faults let through (the first: " +
                       std::to_string(first) + ", " + std::to_string(seen[static_cast<size_t>(first)]) + " message(s), " +
                       std::to_string(expected[static_cast<size_t>(first)]) + " expected)");
  if (outside > 0)
    problems.push_back(channel + ": " + std::to_string(outside) + " message(s) of a cycle outside 0.." + std::to_string(last));
}

// The participants' answers (AXIS_<X>_STATE, HLI_CONTROL), as opposed to
// the CNC's output.
bool is_answer_channel(const std::string& channel) {
  return channel == channels::hli_control || !channels::axis_of_state(channel).empty();
}

}  // namespace

std::vector<std::string> log_problems(const LogFacts& f) {
  std::vector<std::string> p;
  if (!f.manifest) p.push_back("no manifest of the run (HIL_MANIFEST)");
  if (f.manifest && !f.scenario) p.push_back("no scenario (HIL_SCENARIO): the logger did not write it");
  if (!f.sealed) p.push_back("the logger did not close the log (no HIL_LOG_END): it was cut short");
  if (!f.end_cycle) p.push_back("no RUN_END from the cnc");
  // In real time a participant the watchdog lost that still ended left
  // nothing out of the log: its loss is an error event of the run.
  for (const auto& [name, cycle] : f.lost)
    if (!f.faults.touches(name) && !(f.realtime && f.ended.count(name)))
      p.push_back(name + " went silent: the cnc lost it at cycle " + std::to_string(cycle));
  std::vector<std::string> no_end;
  for (const auto& name : f.participants)
    if (!f.ended.count(name) && !f.lost.count(name) && name != "cnc") no_end.push_back(name);
  if (!no_end.empty()) p.push_back("no RUN_END from " + list(no_end));
  std::vector<std::string> not_waited_for;  // the seal names the lost too
  for (const auto& name : f.logger_missing)
    if (!(f.lost.count(name) && f.faults.touches(name))) not_waited_for.push_back(name);
  if (f.sealed && !not_waited_for.empty()) p.push_back("the logger stopped waiting for " + list(not_waited_for));
  if (f.logger_socket_drops > 0)
    p.push_back("the kernel dropped " + std::to_string(f.logger_socket_drops) +
                " datagram(s) at the logger's socket (its receive buffer was full)");
  for (const std::string& what : f.unreadable) p.push_back(what);
  if (f.records_after_seal > 0)
    p.push_back(std::to_string(f.records_after_seal) +
                " record(s) after the logger's seal (HIL_LOG_END), which it writes last");
  if (f.sealed && f.seal_recorded && *f.seal_recorded != f.records_before_seal)
    p.push_back("the logger's seal counts " + std::to_string(*f.seal_recorded) +
                " message(s) written before it, the log holds " + std::to_string(f.records_before_seal));
  if (f.sealed && f.end_cycle && f.seal_cycle && *f.seal_cycle != *f.end_cycle)
    p.push_back("the cnc's RUN_END names cycle " + std::to_string(*f.end_cycle) + ", the logger's seal cycle " +
                std::to_string(*f.seal_cycle));
  // The lock-step channels are checked up to a RUN_END cycle the log can
  // hold: -1 (no cycle ran) .. a bound from what it holds.
  const int64_t held = cycles_held(f);
  const bool end_plausible = f.end_cycle && (f.lock_step.empty() || (*f.end_cycle >= -1 &&
                                                                     *f.end_cycle <= plausible_last_cycle(held)));
  if (f.end_cycle && !end_plausible)
    p.push_back("the cnc's RUN_END names cycle " + std::to_string(*f.end_cycle) +
                (*f.end_cycle < 0 ? std::string(", before the first (0)")
                                  : ", beyond the " + std::to_string(held) + " cycles the log holds"));
  if (end_plausible) {
    for (const auto& [channel, cycles] : f.lock_step) {
      if (f.realtime && is_answer_channel(channel)) continue;  // missing answers are counted in real time
      if (f.faults.touches_channel(channel)) check_planned_cycles(channel, cycles, *f.end_cycle, f.faults, p);
      else check_cycles(channel, cycles, *f.end_cycle, p);
    }
  }
  if (f.realtime && f.end_cycle && !f.rt_stats_final)
    p.push_back("no final real-time statistics (HIL_RT_STATS) from the cnc");
  for (const auto& [who, all] : f.refused) {
    traffic::Ledger ledger;  // without the channels the faults act on
    for (const auto& [channel, counts] : all.by_channel())
      if (!f.faults.touches_channel(channel)) ledger.add(channel, counts);
    if (ledger.fails_run())
      p.push_back((who == "log" ? "in the log" : who + " refused") + std::string(" messages of this run or unreadable: ") +
                  ledger.describe());
  }
  const int verdicts = f.verdict_pass + f.verdict_fail;
  if (f.verdicts_announced && *f.verdicts_announced != verdicts)
    p.push_back("the log holds " + std::to_string(verdicts) + " verdict event(s), plc_sim published " +
                std::to_string(*f.verdicts_announced));
  if (f.expectations >= 0 && verdicts < f.expectations)
    p.push_back("the scenario has " + std::to_string(f.expectations) + " expectation(s), the log holds " +
                std::to_string(verdicts) + " verdict(s)");
  return p;
}

RunVerdict judge_run(const std::vector<ProcessExit>& exits, const LogFacts& facts, const std::string& check_failure) {
  RunVerdict v;
  for (const ProcessExit& e : exits)
    if (!e.status) v.reasons.push_back(e.name + " hung and was killed");
    else if (*e.status != 0 && !(*e.status == 128 + 9 && facts.faults.kill_cycle(e.name)))  // a planned kill
      v.reasons.push_back(e.name + " exited with status " + std::to_string(*e.status));
  for (const std::string& problem : log_problems(facts)) v.reasons.push_back("log: " + problem);
  if (facts.verdict_fail > 0) v.reasons.push_back(std::to_string(facts.verdict_fail) + " expectation(s) failed");
  if (!check_failure.empty()) v.reasons.push_back("offline check: " + check_failure);
  v.passed = v.reasons.empty();
  return v;
}

std::string describe_refused(const LogFacts& facts) {
  std::string out;
  for (const auto& [who, ledger] : facts.refused)
    if (!ledger.empty()) out += (out.empty() ? "" : "\n  ") + who + ": " + ledger.describe();
  return out.empty() ? "none" : "\n  " + out;
}

void Attendance::ended(const std::string& name, int64_t cycle, const std::vector<std::string>& lost) {
  ended_.insert(name);
  if (name != "cnc") return;
  end_cycle_ = cycle;
  lost_.insert(lost.begin(), lost.end());
}

std::vector<std::string> Attendance::missing() const {
  std::vector<std::string> out;
  for (const auto& name : expected_)
    if (!ended_.count(name) && !lost_.count(name)) out.push_back(name);
  return out;
}

}  // namespace hil::logger
