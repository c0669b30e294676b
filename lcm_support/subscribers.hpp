#pragma once
// The subscriptions of a Bus that hands messages on itself (the in-process
// bus, the udpm bus): by channel name, or every channel but LCM_SELF_TEST,
// each message to its subscribers in the order they subscribed.
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "bus.hpp"

namespace hil::lcm_support {

class Subscribers {
 public:
  int add(const std::string& channel, Bus::Handler handler);
  void remove(int id);
  // The channels subscribed by name; `every`: some subscription takes all.
  std::vector<std::string> names(bool& every) const;
  // Hands the message to each subscriber of `channel`. A subscription made
  // or ended by a handler ends the hand-over (the lists are made anew).
  void dispatch(const lcm::ReceiveBuffer& rbuf, const std::string& channel);

 private:
  struct Subscription {
    int id;
    std::string channel;
    Bus::Handler handler;
  };
  const std::vector<const Subscription*>& of(const std::string& channel);

  std::vector<std::unique_ptr<Subscription>> subscriptions_;
  std::unordered_map<std::string, std::vector<const Subscription*>> by_channel_;  // made as channels appear
  int next_id_ = 1;
  int64_t generation_ = 0;
};

}  // namespace hil::lcm_support
