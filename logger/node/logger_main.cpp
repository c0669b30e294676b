// The `hil_logger` node (RIG-1, RIG-4): records every channel of a run into
// a standard LCM event log, with no drops: a deep queue on its one
// subscription and a large socket buffer in the URL.
#include <hil/participant_t.hpp>
#include <lcm/lcm-cpp.hpp>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstring>
#include <set>

#include "channels.hpp"
#include "node_options.hpp"
#include "participant.hpp"

namespace {

using namespace hil;
using clock_type = std::chrono::steady_clock;

class LoggerNode {
 public:
  LoggerNode(lcm::LCM& lcm, const std::string& path) : log_(path, "w") {
    if (!log_.good()) throw std::runtime_error("cannot write log " + path);
    lcm.subscribeFunction(
           ".*",
           +[](const lcm::ReceiveBuffer* rbuf, const std::string& channel, LoggerNode* self) {
             self->record(*rbuf, channel);
           },
           this)
        ->setQueueCapacity(1000000);
  }

  // Every participant that said READY has said RUN_END (the CNC first).
  bool all_ended() const {
    if (!ended_.count("cnc")) return false;
    for (const auto& name : ready_)
      if (name != "logger" && !ended_.count(name)) return false;
    return true;
  }
  bool cnc_ended() const { return ended_.count("cnc") > 0; }
  int64_t recorded() const { return recorded_; }
  void flush() { std::fflush(log_.getFilePtr()); }

 private:
  void record(const lcm::ReceiveBuffer& rbuf, const std::string& channel) {
    lcm::LogEvent event;
    event.timestamp = rbuf.recv_utime;
    event.channel = channel;
    event.datalen = static_cast<int32_t>(rbuf.data_size);
    event.data = rbuf.data;
    if (log_.writeEvent(&event) != 0) throw std::runtime_error("writing the log failed");
    ++recorded_;
    if (channel == channels::participant) {
      hil::participant_t m;
      if (m.decode(rbuf.data, 0, static_cast<int>(rbuf.data_size)) < 0) return;
      (m.phase == hil::participant_t::PHASE_READY ? ready_ : ended_).insert(m.name);
    }
  }

  lcm::LogFile log_;
  std::set<std::string> ready_, ended_;
  int64_t recorded_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hil_logger: records every channel of a rig run into an LCM event log"};
  std::string url, path;
  double linger_s = 3.0;
  app.add_option("--url", url, "LCM URL of the rig")->required();
  app.add_option("--out", path, "log file to write")->required();
  app.add_option("--linger-s", linger_s, "after the CNC's RUN_END, wait at most this long for the others");
  CLI11_PARSE(app, argc, argv);
  return hil::lcm_support::guarded_main("logger", [&] {
    lcm::LCM lcm(url);
    hil::lcm_support::require_good(lcm, url);
    LoggerNode node(lcm, path);
    hil::lcm_support::Participant participant(lcm, "logger");
    if (!participant.wait_for_start(std::chrono::seconds(30))) {
      spdlog::error("the CNC did not start a run within 30 s");
      return 2;
    }
    auto last_message = clock_type::now();
    clock_type::time_point cnc_end{};
    while (!node.all_ended()) {
      const int handled = lcm.handleTimeout(100);
      if (handled < 0) throw std::runtime_error("LCM receive failed");
      const auto now = clock_type::now();
      if (handled > 0) last_message = now;
      if (node.cnc_ended() && cnc_end == clock_type::time_point{}) cnc_end = now;
      if (node.cnc_ended() && now - cnc_end > std::chrono::duration<double>(linger_s)) {
        spdlog::warn("not every participant announced its end within {} s", linger_s);
        break;
      }
      if (!node.cnc_ended() && now - last_message > std::chrono::seconds(10)) {
        spdlog::error("no message for 10 s and no RUN_END from the CNC: log closed early");
        node.flush();
        return 2;
      }
    }
    node.flush();
    spdlog::info("{} messages recorded to {}", node.recorded(), path);
    return 0;
  });
}
