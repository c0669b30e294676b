// RIG-12: what the run's MAC costs a message (docs/PERFORMANCE.md "MAC
// cost"): signing and checking the rig's own messages at their encoded
// sizes, and the copy the signing bus makes; beside it, what one cycle of
// a three-axis rig sends.
#include "command_line.hpp"
#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/participant_t.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "bus.hpp"
#include "call_timer.hpp"
#include "run_secret.hpp"

using namespace hil;

namespace {

struct Sample {
  std::string channel;
  std::vector<uint8_t> bytes;
};

template <typename Message>
Sample sample(const std::string& channel, Message m) {
  m.run_id = 42;
  return {channel, lcm_support::encode(m)};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mac_bench: the time to sign and verify a rig message's MAC, per message type (RIG-12)"};
  app.footer("Documentation: docs/RELIABILITY.md in the source tree");
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  const lcm_support::RunSecret secret = lcm_support::RunSecret::generate();
  hil::axis_state_t state{};
  state.axis = "X";
  hil::participant_t end{};
  end.name = "axis_sim X";
  std::vector<Sample> samples = {sample("AXIS_X_CMD", hil::axis_setpoint_t{}), sample("AXIS_X_STATE", state),
                                 sample("HLI_STATE", hil::hli_state_t{}), sample("HIL_PARTICIPANT", end)};
  std::vector<uint8_t> big(64 * 1024, 7);
  samples.push_back({"HIL_SCENARIO", big});
  const bench::CallTimer timer;
  std::printf("%-16s %7s %12s %12s %12s\n", "message", "bytes", "sign ns", "verify ns", "p99 verify");
  for (Sample& s : samples) {
    const auto sign = timer.time(20000, [&](int) {
      secret.sign(s.channel, s.bytes.data(), s.bytes.size());
      return static_cast<double>(s.bytes.back());
    });
    const auto verify = timer.time(20000, [&](int) {
      return secret.verify(s.channel, s.bytes.data(), s.bytes.size()) ? 1.0 : 0.0;
    });
    std::printf("%-16s %7zu %12.1f %12.1f %12.1f\n", s.channel.c_str(), s.bytes.size(), sign.mean_ns, verify.mean_ns,
                verify.p99_ns);
  }
  return 0;
}
