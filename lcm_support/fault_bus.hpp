#pragma once
// RIG-8: a node's bus with the scenario's faults applied to what the node
// sends (fault_plan.hpp): a message dropped, damaged, sent twice, held back
// until the node sends for its release cycle, or nothing at all once the
// node is killed. In both run modes the same decorator stands between the
// node and its bus, so the processes and the in-process run, and the log,
// see the same faults.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bus.hpp"
#include "fault_plan.hpp"

namespace hil::lcm_support {

class FaultInjectingBus : public Bus {
 public:
  // `participant`: "cnc", "axis_sim X", "plc_sim"; `on_kill` runs when the
  // plan kills it (a process: raise SIGKILL; in-process: nothing, the node
  // just falls silent).
  FaultInjectingBus(Bus& inner, const FaultPlan& plan, std::string participant,
                    std::function<void()> on_kill = nullptr);

  void publish(const std::string& channel, const void* data, uint32_t size) override;
  int subscribe(const std::string& channel, Handler handler, int queue_capacity) override {
    return inner_.subscribe(channel, std::move(handler), queue_capacity);
  }
  void unsubscribe(int id) override { inner_.unsubscribe(id); }
  int handle_timeout(int timeout_ms) override { return inner_.handle_timeout(timeout_ms); }
  traffic::Ledger refused() const override { return inner_.refused(); }

  bool killed() const { return killed_; }

 private:
  struct Held {
    std::string channel;
    std::vector<uint8_t> bytes;
    int64_t cycle;
    int64_t release;
    bool duplicated;
  };
  void send(const std::string& channel, const std::vector<uint8_t>& bytes, bool duplicated);

  Bus& inner_;
  const FaultPlan& plan_;
  std::string participant_;
  std::string answer_;  // the channel whose sending releases what is held ("" for the cnc)
  std::optional<int64_t> kill_;
  std::function<void()> on_kill_;
  bool killed_ = false;
  std::vector<Held> held_;
  std::unique_ptr<Bus> owned_;  // with_faults: the bus it stands before

  friend std::unique_ptr<Bus> with_faults(std::unique_ptr<Bus>, const FaultPlan&, const std::string&);
};

// A process's bus: `bus` itself without faults planned, else `bus` behind
// a FaultInjectingBus that owns it; a kill is SIGKILL to the process.
std::unique_ptr<Bus> with_faults(std::unique_ptr<Bus> bus, const FaultPlan& plan, const std::string& participant);

// The bytes as a damaged message: its fingerprint no longer matches.
void damage(std::vector<uint8_t>& bytes);

}  // namespace hil::lcm_support
