#include "inbox.hpp"

#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/log_summary_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <hil/scenario_text_t.hpp>

#include "channels.hpp"

namespace hil::lcm_support {
namespace {

template <typename Message>
std::optional<Identity> identity(const void* data, uint32_t size) {
  Message m{};  // value-initialised: GCC 12 -Werror=maybe-uninitialized otherwise
  if (!decode(data, size, m)) return std::nullopt;
  return Identity{m.run_id, m.cycle};
}

}  // namespace

std::optional<Identity> identify(const std::string& channel, const void* data, uint32_t size) {
  if (channel == channels::hli_state) return identity<hil::hli_state_t>(data, size);
  if (channel == channels::hli_control) return identity<hil::hli_control_t>(data, size);
  if (channel == channels::event) return identity<hil::event_t>(data, size);
  if (channel == channels::participant) return identity<hil::participant_t>(data, size);
  if (channel == channels::manifest) return identity<hil::run_manifest_t>(data, size);
  if (channel == channels::scenario) return identity<hil::scenario_text_t>(data, size);
  if (channel == channels::log_end) return identity<hil::log_summary_t>(data, size);
  if (!channels::axis_of_command(channel).empty()) return identity<hil::axis_setpoint_t>(data, size);
  if (!channels::axis_of_state(channel).empty()) return identity<hil::axis_state_t>(data, size);
  return std::nullopt;
}

Inbox::~Inbox() {
  for (lcm::Subscription* s : subscriptions_) lcm_.unsubscribe(s);
}

void Inbox::route(const std::string& channel, int queue_capacity, Handler handle) {
  routes_.push_back(std::make_unique<Route>(Route{this, std::move(handle)}));
  lcm::Subscription* s = lcm_.subscribeFunction(
      channel,
      +[](const lcm::ReceiveBuffer* rbuf, const std::string& ch, Route* route) {
        if (!framed(*rbuf)) return route->inbox->ledger_.refuse(traffic::malformed_datagram, traffic::Refusal::undecodable);
        route->handle(*rbuf, ch);
      },
      routes_.back().get());
  s->setQueueCapacity(queue_capacity);
  subscriptions_.push_back(s);
}

std::vector<hil::traffic_count_t> to_message(const traffic::Ledger& ledger) {
  std::vector<hil::traffic_count_t> out;
  for (const auto& [channel, r] : ledger.by_channel()) {
    hil::traffic_count_t m;
    m.channel = channel;
    m.foreign_run = r.foreign_run;
    m.wrong_cycle = r.wrong_cycle;
    m.undecodable = r.undecodable;
    out.push_back(m);
  }
  return out;
}

traffic::Ledger from_message(const std::vector<hil::traffic_count_t>& counts) {
  traffic::Ledger ledger;
  for (const auto& m : counts) ledger.add(m.channel, {m.foreign_run, m.wrong_cycle, m.undecodable});
  return ledger;
}

}  // namespace hil::lcm_support
