#pragma once
// The logger on the bus (RIG-1, RIG-4, RIG-9): records every message of one
// run into a standard LCM event log, with no drops (a deep queue on its
// recording subscription, which leaves out LCM_SELF_TEST:
// channels::every_channel_but_self_test; a large socket buffer in the URL),
// and closes the log only when every participant of the run has announced
// its end — it knows them from hil run (--participants) or from the CNC's
// manifest, not from whom it happened to hear READY. It survives any
// datagram: what is not this run's, or not readable, is counted per channel
// and left out. Its last record (HIL_LOG_END) says it closed the log on
// purpose and what it missed; it writes the resolved scenario
// (HIL_SCENARIO) after the manifest.
#include <hil/run_manifest_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bus.hpp"
#include "event_log_writer.hpp"
#include "inbox.hpp"
#include "fault_plan.hpp"
#include "verdict.hpp"

namespace hil::logger {

class LoggerNode {
 public:
  // run_id 0: the run of the first manifest heard (recording a replay).
  // `scenario`: the resolved scenario file's text and its NC program, or none.
  // `decode_check`: a message is recorded only if it decodes as its
  // channel's type; without it, if its fingerprint and header are the
  // type's (the in-process bus, where no network can cut or forge bytes;
  // read_run_log decodes every record anyway).
  LoggerNode(lcm_support::Bus& bus, const std::string& path, int64_t run_id, std::vector<std::string> participants,
             std::optional<std::pair<std::string, std::string>> scenario, bool decode_check = true);

  const Attendance& attendance() const { return attendance_; }
  bool scenario_mismatch() const { return scenario_mismatch_; }
  int64_t recorded() const { return recorded_; }
  // Messages of the run from others than this logger: the run is alive.
  int64_t heard() const { return heard_; }
  // The last cycle of the run's HLI_STATE recorded (-1: none yet).
  int64_t recorded_cycle() const { return recorded_cycle_; }
  // Called as recorded_cycle() advances (the in-process run's heartbeat).
  void on_progress(std::function<void(int64_t recorded_cycle)> progress) { progress_ = std::move(progress); }
  int64_t dropped() const { return socket_drops_; }  // by the kernel, known after seal()
  // What it did not record, and what its bus refused before (Bus::refused).
  traffic::Ledger refused() const {
    traffic::Ledger all = bus_.refused();
    all.add(refused_);
    return all;
  }

  // The last record: the logger closed the log, and what it missed.
  void seal();
  // After seal(): says what the log lacks; the node's exit status (0: every
  // participant ended, none lost, the scenario was the CNC's).
  int finish(const std::string& path, double linger_s) const;

 private:
  struct Held {
    std::string channel;
    std::vector<uint8_t> data;
    int64_t recv_utime;
  };

  void receive(const lcm::ReceiveBuffer& rbuf, const std::string& channel);
  void adopt_run(int64_t run_id);
  void take(const std::string& channel, const lcm_support::Identity& id, const void* data, uint32_t size,
            int64_t recv_utime);
  void write_scenario(const hil::run_manifest_t& manifest, int64_t recv_utime);
  template <typename Message>
  void write(const std::string& channel, const Message& m, int64_t utime);
  void write_raw(const std::string& channel, const void* data, uint32_t size, int64_t utime);

  lcm_support::Bus& bus_;
  EventLogWriter log_;
  bool decode_check_;
  int64_t run_id_;
  std::optional<std::pair<std::string, std::string>> scenario_;
  FaultPlan faults_;  // the scenario's (RIG-8): whom it may lose by design
  Attendance attendance_;
  bool told_participants_ = false;  // by hil run; else the manifest's
  int64_t recorded_ = 0, heard_ = 0;
  int64_t last_utime_ = 0;  // the latest record's timestamp
  int64_t recorded_cycle_ = -1;
  int64_t socket_drops_ = -1;
  bool scenario_mismatch_ = false;
  traffic::Ledger refused_;
  std::deque<Held> held_;
  std::function<void(int64_t)> progress_;
};

}  // namespace hil::logger
