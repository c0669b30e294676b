#pragma once
// RIG-12: the bus of one of a run's processes. What the node publishes is
// signed with the run's secret (run_secret.hpp) as it goes out; what comes
// in claiming this run's id is handed on only with the run's MAC, else
// refused and counted (traffic::Refusal::unauthenticated, refused()). A
// message of another run is handed on as it is: the receiver counts it as
// foreign (another rig on the port, a replay). The faults of a scenario
// (fault_bus.hpp) stand outside this bus: a damaged message is signed as
// damaged, as a faulty node would send it, and counted as undecodable.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bus.hpp"
#include "run_secret.hpp"
#include "traffic.hpp"

namespace hil::lcm_support {

class AuthenticatedBus : public Bus {
 public:
  AuthenticatedBus(std::unique_ptr<Bus> inner, RunSecret secret, int64_t run_id);

  void publish(const std::string& channel, const void* data, uint32_t size) override;
  int subscribe(const std::string& channel, Handler handler, int queue_capacity) override;
  void unsubscribe(int id) override { inner_->unsubscribe(id); }
  int handle_timeout(int timeout_ms) override { return inner_->handle_timeout(timeout_ms); }
  traffic::Ledger refused() const override;

 private:
  // Whether a received datagram carries the run's MAC, or need not (not
  // this run's); worked out once per datagram, however many subscriptions
  // are handed it.
  bool authentic(const lcm::ReceiveBuffer& rbuf, const std::string& channel);

  std::unique_ptr<Bus> inner_;
  RunSecret secret_;
  int64_t run_id_;
  std::vector<uint8_t> out_;
  traffic::Ledger refused_;
  struct Judged {
    const void* data = nullptr;
    uint32_t size = 0;
    int64_t recv_utime = 0;
    std::string channel;
    bool authentic = false;
  } last_;
};

}  // namespace hil::lcm_support
