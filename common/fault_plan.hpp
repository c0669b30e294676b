#pragma once
// RIG-8: faults declared in a scenario (`faults:`), free of LCM. Each
// message a node publishes on a cycle channel (AXIS_<X>_CMD, HLI_STATE from
// the CNC; AXIS_<X>_STATE from a drive, HLI_CONTROL from the PLC) has a
// fate: sent, dropped, damaged (its type's fingerprint no longer matches, as
// a checksum error on a fieldbus: every receiver refuses it), duplicated, or
// held back until a later cycle (a delayed or frozen participant). A killed
// participant sends nothing from its kill cycle on. The fate is a pure
// function of the plan, the seed, the channel and the cycle, so the sender
// that applies it, the CNC that must not wait for what will not come, and
// the offline check that must not miss what should be in the log all agree,
// and a run with faults is as deterministic as one without.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "machine_config.hpp"

namespace hil {

enum class FaultKind { drop, corrupt, duplicate, delay, freeze, kill };

struct Fault {
  FaultKind kind = FaultKind::drop;
  std::string channel;      // drop, corrupt, duplicate: the cycle channel
  std::string participant;  // delay, freeze, kill: "axis_sim X" or "plc_sim"
  double percent = 100;     // drop, corrupt, duplicate: the share of the window's messages
  int64_t from_cycle = 0;   // the window [from, until) of cycles
  int64_t until_cycle = std::numeric_limits<int64_t>::max();
  int64_t delay_cycles = 0;  // delay: in lock-step (ms given: rounded up to whole cycles)
  double delay_ms = 0;       // delay as given in ms, 0 if given in cycles (real time: wall ms)
};

// What becomes of the message on `channel` for a cycle.
struct MessageFate {
  bool dropped = false;
  bool corrupted = false;
  bool duplicated = false;
  int64_t release_cycle = 0;  // sent when its sender publishes for this cycle or later

  // How many undamaged copies reach the receivers.
  int copies() const { return dropped || corrupted ? 0 : duplicated ? 2 : 1; }
};

class FaultPlan {
 public:
  uint64_t seed = 1;
  std::vector<Fault> faults;

  bool empty() const { return faults.empty(); }
  MessageFate fate(const std::string& channel, int64_t cycle) const;
  // The cycle from which `participant` sends nothing (it is killed), if any.
  std::optional<int64_t> kill_cycle(const std::string& participant) const;
  // Whether a fault acts on the participant or a channel of its (it may then
  // be lost, refuse messages, miss cycles).
  bool touches(const std::string& participant) const;
  bool touches_channel(const std::string& channel) const;
};

// The participant answering on a cycle channel, or the CNC for its output.
std::string sender_of(const std::string& channel);
// A participant's input (from the CNC) and answer channels.
std::string input_channel(const std::string& participant);
std::string answer_channel(const std::string& participant);

// The `faults:` list and `fault_seed:` of a scenario, checked against the
// machine (its axes, cycle time); throws ConfigError naming the entry.
FaultPlan parse_fault_plan(const YAML::Node& faults, const YAML::Node& seed, const MachineConfig& machine);

// In lock-step, which answers of one participant reach the CNC in each
// cycle when the plan acts on it; call arrivals(0), arrivals(1), ... in
// order. It follows the senders' rules: a participant answers each cycle
// whose input it got undamaged, until its kill cycle; an answer held back
// goes out with its first answer at or after its release cycle.
class AnswerSchedule {
 public:
  AnswerSchedule(const FaultPlan& plan, std::string participant);
  // The cycles whose answers arrive undamaged in cycle `cycle`, each as
  // often as it is sent (a duplicate twice).
  std::vector<int64_t> arrivals(int64_t cycle);

 private:
  struct Held {
    int64_t cycle;
    int64_t release;
    int copies;
  };
  const FaultPlan& plan_;
  std::string participant_, input_, answer_;
  std::optional<int64_t> kill_;
  std::vector<Held> held_;
};

}  // namespace hil
