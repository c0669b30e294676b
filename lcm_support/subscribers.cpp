#include "subscribers.hpp"

#include "channels.hpp"

namespace hil::lcm_support {

int Subscribers::add(const std::string& channel, Bus::Handler handler) {
  subscriptions_.push_back(std::make_unique<Subscription>(Subscription{next_id_, channel, std::move(handler)}));
  by_channel_.clear();
  ++generation_;
  return next_id_++;
}

void Subscribers::remove(int id) {
  for (auto it = subscriptions_.begin(); it != subscriptions_.end(); ++it)
    if ((*it)->id == id) {
      subscriptions_.erase(it);
      by_channel_.clear();
      ++generation_;
      return;
    }
}

std::vector<std::string> Subscribers::names(bool& every) const {
  every = false;
  std::vector<std::string> out;
  for (const auto& s : subscriptions_) {
    if (s->channel == channels::every_channel_but_self_test) every = true;
    else out.push_back(s->channel);
  }
  return out;
}

const std::vector<const Subscribers::Subscription*>& Subscribers::of(const std::string& channel) {
  const auto known = by_channel_.find(channel);
  if (known != by_channel_.end()) return known->second;
  std::vector<const Subscription*>& list = by_channel_[channel];
  for (const auto& s : subscriptions_)
    if (s->channel == channel ||
        (s->channel == channels::every_channel_but_self_test && channel != channels::lcm_self_test))
      list.push_back(s.get());
  return list;
}

void Subscribers::dispatch(const lcm::ReceiveBuffer& rbuf, const std::string& channel) {
  const std::vector<const Subscription*>& to = of(channel);
  const int64_t generation = generation_;
  for (size_t i = 0; i < to.size() && generation == generation_; ++i) to[i]->handler(rbuf, channel);
}

}  // namespace hil::lcm_support
