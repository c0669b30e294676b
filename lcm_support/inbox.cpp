#include "inbox.hpp"

#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/log_summary_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/rt_stats_t.hpp>
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

int64_t big_endian_64(const uint8_t* p) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v = v << 8 | p[i];
  return static_cast<int64_t>(v);
}

// Every rig type begins with its fingerprint, run_id, utime and cycle (lcmtypes/).
template <typename Message>
std::optional<Identity> header(const void* data, uint32_t size) {
  const auto* p = static_cast<const uint8_t*>(data);
  if (size < 32 || big_endian_64(p) != Message::getHash()) return std::nullopt;
  return Identity{big_endian_64(p + 8), big_endian_64(p + 24)};
}

template <typename T>
struct Type {
  using type = T;
};

// read(Type<M>{}) with M the rig channel's type; none for another channel.
template <typename Read>
std::optional<Identity> as_channel_type(const std::string& channel, Read read) {
  if (channel == channels::hli_state) return read(Type<hil::hli_state_t>{});
  if (channel == channels::hli_control) return read(Type<hil::hli_control_t>{});
  if (channel == channels::event) return read(Type<hil::event_t>{});
  if (channel == channels::participant) return read(Type<hil::participant_t>{});
  if (channel == channels::manifest) return read(Type<hil::run_manifest_t>{});
  if (channel == channels::scenario) return read(Type<hil::scenario_text_t>{});
  if (channel == channels::log_end) return read(Type<hil::log_summary_t>{});
  if (channel == channels::rt_stats) return read(Type<hil::rt_stats_t>{});
  if (channels::names_an_axis(channel, "_CMD")) return read(Type<hil::axis_setpoint_t>{});
  if (channels::names_an_axis(channel, "_STATE")) return read(Type<hil::axis_state_t>{});
  return std::nullopt;
}

}  // namespace

std::optional<int64_t> named_run_id(const void* data, uint32_t size) {
  if (size < 16) return std::nullopt;
  return big_endian_64(static_cast<const uint8_t*>(data) + 8);
}

std::optional<Identity> identify(const std::string& channel, const void* data, uint32_t size) {
  return as_channel_type(channel, [&](auto type) { return identity<typename decltype(type)::type>(data, size); });
}

std::optional<Identity> identify_header(const std::string& channel, const void* data, uint32_t size) {
  return as_channel_type(channel, [&](auto type) { return header<typename decltype(type)::type>(data, size); });
}

Inbox::~Inbox() {
  for (int id : subscriptions_) bus_.unsubscribe(id);
}

void Inbox::route(const std::string& channel, int queue_capacity, Bus::Handler handle) {
  subscriptions_.push_back(bus_.subscribe(
      channel,
      [this, handle = std::move(handle)](const lcm::ReceiveBuffer& rbuf, const std::string& ch) {
        if (!framed(rbuf)) return ledger_.refuse(traffic::malformed_datagram, traffic::Refusal::undecodable);
        handle(rbuf, ch);
      },
      queue_capacity));
}

std::vector<hil::traffic_count_t> to_message(const traffic::Ledger& ledger) {
  std::vector<hil::traffic_count_t> out;
  for (const auto& [channel, r] : ledger.by_channel()) {
    hil::traffic_count_t m;
    m.channel = channel;
    m.foreign_run = r.foreign_run;
    m.wrong_cycle = r.wrong_cycle;
    m.undecodable = r.undecodable;
    m.unauthenticated = r.unauthenticated;
    m.oversized = r.oversized;
    out.push_back(m);
  }
  return out;
}

traffic::Ledger from_message(const std::vector<hil::traffic_count_t>& counts) {
  traffic::Ledger ledger;
  for (const auto& m : counts) ledger.add(m.channel, {m.foreign_run, m.wrong_cycle, m.undecodable, m.unauthenticated, m.oversized});
  return ledger;
}

}  // namespace hil::lcm_support
