#include "fault_plan.hpp"
#include "file_keys.hpp"

#include <algorithm>
#include <cmath>

#include "config_error.hpp"

namespace hil {
namespace {

uint64_t splitmix(uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// The same draw for the same seed, fault, channel and cycle, wherever made.
double chance(uint64_t seed, size_t fault, const std::string& channel, int64_t cycle) {
  uint64_t h = splitmix(seed ^ (static_cast<uint64_t>(fault) << 32));
  for (const char c : channel) h = splitmix(h ^ static_cast<unsigned char>(c));
  h = splitmix(h ^ static_cast<uint64_t>(cycle));
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

bool in_window(const Fault& f, int64_t cycle) { return cycle >= f.from_cycle && cycle < f.until_cycle; }

const std::vector<std::pair<std::string, FaultKind>> kinds = {
    {"drop", FaultKind::drop},   {"corrupt", FaultKind::corrupt}, {"duplicate", FaultKind::duplicate},
    {"delay", FaultKind::delay}, {"freeze", FaultKind::freeze},   {"kill", FaultKind::kill}};

bool on_channel(FaultKind k) { return k == FaultKind::drop || k == FaultKind::corrupt || k == FaultKind::duplicate; }

}  // namespace

std::string sender_of(const std::string& channel) {
  if (channel == "HLI_STATE") return "cnc";
  if (channel == "HLI_CONTROL") return "plc_sim";
  if (channel.size() == 12 && channel.rfind("AXIS_", 0) == 0 && channel.compare(6, 6, "_STATE") == 0)
    return "axis_sim " + channel.substr(5, 1);
  if (channel.size() == 10 && channel.rfind("AXIS_", 0) == 0 && channel.compare(6, 4, "_CMD") == 0) return "cnc";
  return "";
}

namespace {
bool is_drive(const std::string& participant) { return participant.size() == 10 && participant.rfind("axis_sim ", 0) == 0; }
}  // namespace

std::string input_channel(const std::string& participant) {
  if (participant == "plc_sim") return "HLI_STATE";
  return is_drive(participant) ? "AXIS_" + participant.substr(9) + "_CMD" : "";
}

std::string answer_channel(const std::string& participant) {
  if (participant == "plc_sim") return "HLI_CONTROL";
  return is_drive(participant) ? "AXIS_" + participant.substr(9) + "_STATE" : "";
}

MessageFate FaultPlan::fate(const std::string& channel, int64_t cycle) const {
  MessageFate f;
  f.release_cycle = cycle;
  for (size_t i = 0; i < faults.size(); ++i) {
    const Fault& x = faults[i];
    if (!in_window(x, cycle)) continue;
    if (on_channel(x.kind)) {
      if (x.channel != channel || chance(seed, i, channel, cycle) * 100 >= x.percent) continue;
      if (x.kind == FaultKind::drop) f.dropped = true;
      if (x.kind == FaultKind::corrupt) f.corrupted = true;
      if (x.kind == FaultKind::duplicate) f.duplicated = true;
    } else if (answer_channel(x.participant) == channel) {
      if (x.kind == FaultKind::delay) f.release_cycle = std::max(f.release_cycle, cycle + x.delay_cycles);
      if (x.kind == FaultKind::freeze) f.release_cycle = std::max(f.release_cycle, x.until_cycle);
    }
  }
  return f;
}

std::optional<int64_t> FaultPlan::kill_cycle(const std::string& participant) const {
  std::optional<int64_t> at;
  for (const Fault& x : faults)
    if (x.kind == FaultKind::kill && x.participant == participant) at = std::min(at.value_or(x.from_cycle), x.from_cycle);
  return at;
}

bool FaultPlan::touches(const std::string& participant) const {
  for (const Fault& x : faults)
    if (x.participant == participant || (!x.channel.empty() && (x.channel == input_channel(participant) ||
                                                                x.channel == answer_channel(participant))))
      return true;
  return false;
}

bool FaultPlan::touches_channel(const std::string& channel) const {
  const std::string sender = sender_of(channel);
  for (const Fault& x : faults) {
    if (x.channel == channel) return true;
    // a participant held back or killed: its answers, and the input it no longer reads
    if (!x.participant.empty() && (answer_channel(x.participant) == channel || input_channel(x.participant) == channel))
      return true;
    // its input lost or damaged: no answer to it
    if (!x.channel.empty() && sender != "cnc" && !sender.empty() && input_channel(sender) == x.channel) return true;
  }
  return false;
}

FaultPlan parse_fault_plan(const YAML::Node& faults, const YAML::Node& seed, const MachineConfig& machine) {
  FaultPlan plan;
  if (seed && !seed.IsNull()) plan.seed = static_cast<uint64_t>(config_whole(seed, "fault_seed", 0, std::numeric_limits<int64_t>::max()));
  if (!faults || faults.IsNull()) return plan;
  if (!faults.IsSequence()) throw ConfigError("faults: must be a list");
  const double cycle_s = machine.cycle_time_s();
  auto cycles = [&](double s) { return static_cast<int64_t>(std::llround(s / cycle_s)); };
  const double max_s = 1e7;
  for (size_t i = 0; i < faults.size(); ++i) {
    const std::string where = index_path("faults", i);
    if (!faults[i].IsMap()) throw ConfigError(where + ": must be a mapping, e.g. {drop: AXIS_X_STATE, percent: 5}");
    std::string kind_key;
    Fault f;
    for (const auto& [name, kind] : kinds)
      if (faults[i][name]) {
        if (!kind_key.empty()) throw ConfigError(where + ": one fault per entry ('" + kind_key + "' and '" + name + "')");
        kind_key = name;
        f.kind = kind;
      }
    if (kind_key.empty())
      throw ConfigError(where + ": names no fault (drop, corrupt, duplicate, delay, freeze or kill)");
    std::vector<std::string> keys = {kind_key};
    if (on_channel(f.kind)) keys.insert(keys.end(), {"percent", "at_s", "from_s", "until_s"});
    if (f.kind == FaultKind::delay) keys.insert(keys.end(), {"cycles", "ms", "from_s", "until_s"});
    if (f.kind == FaultKind::freeze) keys.insert(keys.end(), {"at_s", "for_s"});
    if (f.kind == FaultKind::kill) keys.insert(keys.end(), {"at_s"});
    const ConfigMap m(faults[i], where, keys);
    const std::string target = m.text(kind_key);
    if (on_channel(f.kind)) {
      f.channel = target;
      const std::string sender = sender_of(target);
      if (sender.empty() || (sender != "cnc" && sender != "plc_sim" && machine.axis_index(sender.substr(9)) < 0) ||
          (target.rfind("AXIS_", 0) == 0 && machine.axis_index(target.substr(5, 1)) < 0))
        throw ConfigError(m.path(kind_key) + ": '" + target +
                          "' is no cycle channel of this machine (AXIS_<X>_CMD, AXIS_<X>_STATE, HLI_STATE, HLI_CONTROL)");
      m.get("percent", f.percent, Bounds{0, 100});
      if (m.has("at_s") && (m.has("from_s") || m.has("until_s")))
        throw ConfigError(where + ": 'at_s' (one message) or a window 'from_s'/'until_s', not both");
    } else {
      f.participant = target;
      const bool axis = target.rfind("axis_sim ", 0) == 0 && target.size() == 10 && machine.axis_index(target.substr(9)) >= 0;
      if (!axis && target != "plc_sim")
        throw ConfigError(m.path(kind_key) + ": '" + target + "' is no participant of this machine ('axis_sim <X>' or 'plc_sim')");
    }
    if (m.has("at_s")) {
      f.from_cycle = cycles(m.number("at_s", Bounds{0, max_s}));
      f.until_cycle = f.from_cycle + 1;
    }
    if (m.has("from_s")) f.from_cycle = cycles(m.number("from_s", Bounds{0, max_s}));
    if (m.has("until_s")) f.until_cycle = cycles(m.number("until_s", Bounds{0, max_s}));
    if (f.until_cycle <= f.from_cycle) throw ConfigError(where + ": the window ends before it begins");
    if (f.kind == FaultKind::delay) {
      if (m.has("cycles") == m.has("ms")) throw ConfigError(where + ": a delay in 'cycles' or in 'ms' (one of them)");
      if (m.has("cycles")) f.delay_cycles = m.whole("cycles", 1, 1000000);
      if (m.has("ms")) {
        f.delay_ms = m.number("ms", Bounds{0, 1e6, true});
        f.delay_cycles = static_cast<int64_t>(std::ceil(f.delay_ms * 1000 / machine.cycle_time_us - 1e-9));
      }
    }
    if (f.kind == FaultKind::freeze) {
      if (!m.has("at_s") || !m.has("for_s")) throw ConfigError(where + ": a freeze needs 'at_s' and 'for_s'");
      f.until_cycle = f.from_cycle + std::max<int64_t>(1, cycles(m.number("for_s", Bounds{0, max_s, true})));
    }
    if (f.kind == FaultKind::kill) {
      if (!m.has("at_s") || f.from_cycle < 1)
        throw ConfigError(where + ": a kill needs 'at_s', at cycle 1 or later (the participant must have started)");
      f.until_cycle = std::numeric_limits<int64_t>::max();
    }
    plan.faults.push_back(f);
  }
  return plan;
}

AnswerSchedule::AnswerSchedule(const FaultPlan& plan, std::string participant)
    : plan_(plan), participant_(std::move(participant)), input_(input_channel(participant_)),
      answer_(answer_channel(participant_)), kill_(plan.kill_cycle(participant_)) {}

std::vector<int64_t> AnswerSchedule::arrivals(int64_t cycle) {
  std::vector<int64_t> out;
  if (kill_ && cycle >= *kill_) return out;
  const MessageFate input = plan_.fate(input_, cycle);
  if (input.copies() == 0) return out;  // no input, no answer: held ones wait
  // The participant answers `cycle`: first what it held and may now send.
  std::stable_sort(held_.begin(), held_.end(), [](const Held& a, const Held& b) { return a.cycle < b.cycle; });
  for (auto it = held_.begin(); it != held_.end();) {
    if (it->release > cycle) {
      ++it;
      continue;
    }
    for (int c = 0; c < it->copies; ++c) out.push_back(it->cycle);
    it = held_.erase(it);
  }
  const MessageFate answer = plan_.fate(answer_, cycle);
  const int copies = answer.copies();
  if (copies == 0) return out;
  if (answer.release_cycle > cycle) {
    held_.push_back({cycle, answer.release_cycle, copies});
    return out;
  }
  for (int c = 0; c < copies; ++c) out.push_back(cycle);
  return out;
}

const std::vector<std::string>& file_keys::fault() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> all;
    for (const auto& [name, kind] : kinds) all.push_back(name);
    all.insert(all.end(), {"percent", "at_s", "from_s", "until_s", "cycles", "ms", "for_s"});
    return all;
  }();
  return keys;
}

}  // namespace hil
