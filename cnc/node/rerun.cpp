#include "rerun.hpp"

#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <deque>
#include <map>
#include <sstream>
#include <stdexcept>

#include "channel.hpp"
#include "channels.hpp"
#include "cycle_messages.hpp"
#include "messages.hpp"
#include "cycle_loop.hpp"
#include "scenario.hpp"

namespace hil::cnc_node {
namespace {

template <typename T>
bool decode(const void* data, size_t size, T& message) {
  return message.decode(data, 0, static_cast<int>(size)) == static_cast<int>(size);
}

// What the recorded run holds: the inputs to replay and the outputs to match.
struct Recording {
  std::optional<Scenario> scenario;
  std::map<int64_t, HliControl> controls;                // by the cycle they answer
  std::map<int64_t, std::vector<int32_t>> drive_errors;  // by cycle, per axis
  std::map<std::string, std::deque<std::string>> outputs;  // the CNC's messages per channel
};

Recording read_recording(const std::string& path) {
  lcm::LogFile file(path, "r");
  if (!file.good()) throw std::runtime_error("cannot open LCM log " + path);
  Recording r;
  while (const lcm::LogEvent* e = file.readNextEvent()) {
    const std::string& ch = e->channel;
    const size_t n = static_cast<size_t>(e->datalen);
    if (ch == channels::manifest) {
      hil::run_manifest_t m;
      if (decode(e->data, n, m)) r.scenario = parse_scenario(YAML::Load(m.scenario_yaml));
    } else if (ch == channels::hli_control) {
      hil::hli_control_t m;
      if (decode(e->data, n, m)) r.controls[m.cycle] = lcm_support::from_message(m);
    } else if (r.scenario && !channels::axis_of_state(ch).empty()) {
      hil::axis_state_t m;
      const int axis = r.scenario->machine.axis_index(channels::axis_of_state(ch));
      if (axis < 0 || !decode(e->data, n, m)) continue;
      auto& errors = r.drive_errors[m.cycle];
      errors.resize(r.scenario->machine.axes.size(), 0);
      errors[axis] = m.errors;
    } else if (ch == channels::hli_state || !channels::axis_of_command(ch).empty()) {
      r.outputs[ch].emplace_back(static_cast<const char*>(e->data), n);
    } else if (ch == channels::event) {
      hil::event_t m;
      if (decode(e->data, n, m) && m.source == "cnc") r.outputs[ch].emplace_back(static_cast<const char*>(e->data), n);
    }
  }
  if (!r.scenario) throw std::runtime_error(path + ": no manifest (HIL_MANIFEST): nothing to rerun");
  return r;
}

// The fields that differ, for people.
std::string describe_difference(const std::string& channel, const std::string& recorded, const std::string& now) {
  std::ostringstream o;
  o.precision(12);
  if (channel == channels::hli_state) {
    hil::hli_state_t a, b;
    if (decode(recorded.data(), recorded.size(), a) && decode(now.data(), now.size(), b))
      o << "recorded channel_state " << int(a.channel_state) << " block_nr_r " << a.block_nr_r << " dist_prog_start "
        << a.dist_prog_start << " path_velocity " << a.path_velocity << "; this build " << int(b.channel_state)
        << " " << b.block_nr_r << " " << b.dist_prog_start << " " << b.path_velocity;
  } else if (channel == channels::event) {
    hil::event_t a, b;
    if (decode(recorded.data(), recorded.size(), a) && decode(now.data(), now.size(), b))
      o << "recorded \"" << a.message << "\"; this build \"" << b.message << "\"";
  } else {
    hil::axis_setpoint_t a, b;
    if (decode(recorded.data(), recorded.size(), a) && decode(now.data(), now.size(), b))
      o << "recorded position " << a.position << " velocity " << a.velocity << " acceleration " << a.acceleration
        << "; this build " << b.position << " " << b.velocity << " " << b.acceleration << " (mm, mm/s, mm/s^2)";
  }
  if (o.str().empty())  // a message type this build no longer decodes
    return "the recorded message does not decode as this build's " + channel +
           " type (recorded by a build with another message layout)";
  return o.str();
}

// RIG-7 recorded input: the answers to each cycle come from the recording,
// and what this build publishes must match what the recorded CNC did, byte
// for byte.
class RecordedInput : public cnc::CyclePolicy {
 public:
  RecordedInput(Recording recording, std::ostream& out) : rec_(std::move(recording)), out_(out) {}

  bool publish(int64_t k, const cnc::Channel& channel, const std::vector<Event>& events) override {
    for (const auto& m : cycle_messages(channel, machine(), events, k))
      if (!matches(k, m)) return false;
    return true;
  }
  bool publish_event(int64_t k, const Event& event) override { return matches(k, event_message(event, machine(), k)); }
  std::optional<cnc::CycleAnswers> answers(int64_t k) override {
    cnc::CycleAnswers answers;
    if (const auto c = rec_.controls.find(k); c != rec_.controls.end()) answers.control = c->second;
    if (const auto e = rec_.drive_errors.find(k); e != rec_.drive_errors.end())
      answers.drive_errors = drive_errors(machine(), e->second);
    return answers;
  }

  const Scenario& scenario() const { return *rec_.scenario; }
  int64_t compared() const { return compared_; }
  // False (and says so) if the recorded CNC published more than this build.
  bool nothing_left(int64_t k) const {
    for (const auto& [name, queue] : rec_.outputs)
      if (!queue.empty()) {
        out_ << "differs: this build ended after cycle " << k << ", the recorded run has " << queue.size()
             << " more message(s) on " << name << '\n';
        return false;
      }
    return true;
  }

 private:
  const MachineConfig& machine() const { return rec_.scenario->machine; }
  bool matches(int64_t k, const EncodedMessage& m) {
    auto& queue = rec_.outputs[m.channel];
    const std::string now(m.bytes.begin(), m.bytes.end());
    if (queue.empty()) {
      out_ << "differs at cycle " << k << ": " << m.channel << ": this build publishes a message the recorded run has not\n";
      return false;
    }
    if (queue.front() != now) {
      out_ << "differs at cycle " << k << ": " << m.channel << ": " << describe_difference(m.channel, queue.front(), now)
           << '\n';
      return false;
    }
    queue.pop_front();
    ++compared_;
    return true;
  }

  Recording rec_;
  std::ostream& out_;
  int64_t compared_ = 0;
};

}  // namespace

int rerun(const std::string& log_path, std::ostream& out) {
  RecordedInput input(read_recording(log_path), out);
  cnc::Channel channel(input.scenario().machine, input.scenario().nc_program);
  const cnc::CycleLoopResult result = cnc::run_cycles(channel, input.scenario(), input);
  if (result.outcome == cnc::RunOutcome::publish_refused || !input.nothing_left(result.last_cycle)) return 1;
  out << "identical: " << result.last_cycle + 1 << " cycles, " << input.compared()
      << " messages of the CNC (setpoints, HLI state, events)\n";
  return 0;
}

}  // namespace hil::cnc_node
