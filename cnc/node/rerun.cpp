#include "rerun.hpp"

#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <hil/scenario_text_t.hpp>

#include <deque>
#include <map>
#include <sstream>
#include <stdexcept>

#include "channel.hpp"
#include "channels.hpp"
#include "cycle_loop.hpp"
#include "cycle_messages.hpp"
#include "event_log_reader.hpp"
#include "inbox.hpp"
#include "lock_step.hpp"
#include "messages.hpp"
#include "run_identity.hpp"
#include "run_secret.hpp"
#include "scenario.hpp"
#include "untrusted_decode.hpp"

namespace hil::cnc_node {
namespace {

// The recording's bytes (a log file: nobody vouches for them) and this
// build's own, decoded without a throw or a crash.
template <typename Message>
bool decode(const void* data, size_t size, Message& m) {
  return lcm_support::decode_untrusted(data, size, m);
}

// What the recorded run holds: the inputs to replay and the outputs to match.
struct Recording {
  std::optional<Scenario> scenario;
  int64_t run_id = 0;
  int answer_timeout_ms = 0;
  std::map<int64_t, HliControl> controls;  // by the cycle they answer
  std::map<int64_t, std::vector<std::optional<int32_t>>> axis_errors;  // by cycle, per axis: the answer's bits
  std::map<std::string, int64_t> lost;     // participants the CNC lost, and the cycle
  std::map<std::string, std::deque<std::string>> outputs;  // the CNC's messages per channel
};

Recording read_recording(const std::string& path) {
  logger::EventLogReader file(path);
  Recording r;
  while (const logger::LogRecord* e = file.next()) {
    const std::string& ch = e->channel;
    const size_t n = e->data.size();
    const uint8_t* data = e->data.data();
    if (ch == channels::manifest) {
      hil::run_manifest_t m;
      if (!decode(data, n, m)) continue;
      r.run_id = m.run_id;
      r.answer_timeout_ms = m.answer_timeout_ms;
    } else if (ch == channels::scenario) {
      hil::scenario_text_t m;
      if (decode(data, n, m)) r.scenario = scenario_from_text(m.yaml, m.nc_program);
    } else if (ch == channels::participant) {
      hil::participant_t m;
      if (!decode(data, n, m) || m.name != "cnc") continue;
      for (size_t i = 0; i < m.lost.size(); ++i) r.lost[m.lost[i]] = m.lost_cycle[i];
    } else if (ch == channels::hli_control) {
      hil::hli_control_t m;
      if (decode(data, n, m)) r.controls.emplace(m.cycle, lcm_support::from_message(m));
    } else if (r.scenario && !channels::axis_of_state(ch).empty()) {
      hil::axis_state_t m;
      const int axis = r.scenario->machine.axis_index(channels::axis_of_state(ch));
      if (axis < 0 || !decode(data, n, m)) continue;
      auto& errors = r.axis_errors[m.cycle];
      errors.resize(r.scenario->machine.axes.size());
      if (!errors[axis]) errors[axis] = m.errors;
    } else if (ch == channels::hli_state || !channels::axis_of_command(ch).empty()) {
      r.outputs[ch].emplace_back(reinterpret_cast<const char*>(data), n);
    } else if (ch == channels::event) {
      hil::event_t m;
      if (decode(data, n, m) && m.source == "cnc") r.outputs[ch].emplace_back(reinterpret_cast<const char*>(data), n);
    }
  }
  if (file.records() == 0) throw std::runtime_error(path + " is not an LCM event log (no event found)");
  // Its outputs would be compared with a recording that has holes.
  if (file.damage().any())
    throw std::runtime_error(path + " is damaged: " + file.damage().describe() + "; hil rerun reruns whole logs only");
  if (!r.scenario) throw std::runtime_error(path + ": no scenario (HIL_SCENARIO): nothing to rerun");
  // RIG-6: in real time an answer went into the cycle it arrived in, which
  // the log does not record (only the cycle it answered).
  if (r.scenario->realtime)
    throw std::runtime_error(path + ": a real-time run (run.realtime): its answers were taken when they arrived, "
                                    "which the log does not hold; hil rerun reruns lock-step logs only");
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
  RecordedInput(Recording recording, std::ostream& out)
      : rec_(std::move(recording)), out_(out),
        lock_step_(machine(), false, rec_.answer_timeout_ms, 0, &rec_.scenario->faults) {}

  bool publish(int64_t k, const cnc::Channel& channel, const std::vector<Event>& events) override {
    for (const auto& m : cycle_messages(channel, machine(), events, k, rec_.run_id))
      if (!matches(k, m)) return false;
    return true;
  }
  bool publish_event(int64_t k, const Event& event) override {
    return matches(k, event_message(event, machine(), k, rec_.run_id));
  }
  // The recorded answers go through the live node's LockStep, those due in
  // the cycle (its own answer; with faults planned, what the plan lets arrive
  // then, RIG-8); an answer the recorded CNC no longer took (from a
  // participant it had lost) is left out.
  std::optional<cnc::CycleAnswers> answers(int64_t k) override {
    lock_step_.begin(k);
    if (!lost_by("plc_sim", k))
      for (const int64_t c : std::vector<int64_t>(lock_step_.awaited_plc()))
        if (const auto control = rec_.controls.find(c); control != rec_.controls.end())
          lock_step_.take_plc(c, control->second);
    for (size_t i = 0; i < machine().axes.size(); ++i) {
      if (lost_by("axis_sim " + machine().axes[i].name, k)) continue;
      for (const int64_t c : std::vector<int64_t>(lock_step_.awaited_axis(i)))
        if (const auto e = rec_.axis_errors.find(c); e != rec_.axis_errors.end() && e->second[i])
          lock_step_.take_axis(i, c, *e->second[i]);
    }
    if (!lock_step_.complete()) lock_step_.lose_silent();
    LockStep::Taken taken = lock_step_.take();
    return cnc::CycleAnswers{taken.control, drive_errors(machine(), taken.axis_errors), std::move(taken.lost)};
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
  bool lost_by(const std::string& participant, int64_t k) const {
    const auto lost = rec_.lost.find(participant);
    return lost != rec_.lost.end() && lost->second <= k;
  }
  bool matches(int64_t k, const EncodedMessage& m) {
    auto& queue = rec_.outputs[m.channel];
    const std::string now(m.bytes.begin(), m.bytes.end());
    // The recorded MAC is the run's (RIG-12); this build's messages carry none.
    auto unsigned_part = [](const std::string& bytes) {
      return bytes.substr(0, bytes.size() - std::min(bytes.size(), lcm_support::RunSecret::mac_bytes));
    };
    if (queue.empty()) {
      out_ << "differs at cycle " << k << ": " << m.channel << ": this build publishes a message the recorded run has not\n";
      return false;
    }
    if (unsigned_part(queue.front()) != unsigned_part(now)) {
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
  LockStep lock_step_;
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
