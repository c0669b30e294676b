#include "authenticated_bus.hpp"

#include "inbox.hpp"

namespace hil::lcm_support {

AuthenticatedBus::AuthenticatedBus(std::unique_ptr<Bus> inner, RunSecret secret, int64_t run_id)
    : inner_(std::move(inner)), secret_(std::move(secret)), run_id_(run_id) {}

void AuthenticatedBus::publish(const std::string& channel, const void* data, uint32_t size) {
  out_.assign(static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + size);
  secret_.sign(channel, out_.data(), out_.size());
  inner_->publish(channel, out_.data(), size);
}

int AuthenticatedBus::subscribe(const std::string& channel, Handler handler, int queue_capacity) {
  return inner_->subscribe(
      channel,
      [this, handler = std::move(handler)](const lcm::ReceiveBuffer& rbuf, const std::string& ch) {
        if (authentic(rbuf, ch)) handler(rbuf, ch);
      },
      queue_capacity);
}

bool AuthenticatedBus::authentic(const lcm::ReceiveBuffer& rbuf, const std::string& channel) {
  if (rbuf.data == last_.data && rbuf.data_size == last_.size && rbuf.recv_utime == last_.recv_utime &&
      channel == last_.channel)
    return last_.authentic;
  // Unframed bytes and other runs' messages go on: the receiver counts them.
  const bool authentic = rbuf.data_size > LCM_MAX_MESSAGE_SIZE || named_run_id(rbuf.data, rbuf.data_size) != run_id_ ||
                         secret_.verify(channel, static_cast<const uint8_t*>(rbuf.data), rbuf.data_size);
  if (!authentic) refused_.refuse(channel, traffic::Refusal::unauthenticated);
  last_ = {rbuf.data, rbuf.data_size, rbuf.recv_utime, channel, authentic};
  return authentic;
}

traffic::Ledger AuthenticatedBus::refused() const {
  traffic::Ledger all = inner_->refused();
  all.add(refused_);
  return all;
}

}  // namespace hil::lcm_support
