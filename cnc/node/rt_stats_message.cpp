#include "rt_stats_message.hpp"

#include <hil/rt_stats_t.hpp>

#include "bus.hpp"
#include "channels.hpp"

namespace hil::cnc_node {

EncodedMessage rt_stats_message(const Ticker& ticker, const RealTimeAnswers& answers, const std::string& scheduling,
                                int64_t cycle, int32_t cycle_us, int64_t run_id, bool final) {
  hil::rt_stats_t m;
  m.run_id = run_id;
  m.cycle = cycle;
  m.utime = cycle * cycle_us;
  m.is_final = final;
  m.cycle_us = cycle_us;
  m.scheduling = scheduling;
  const JitterStats& j = ticker.jitter();
  m.ticks = j.count();
  m.overruns = ticker.overruns();
  m.jitter_p50_us = j.quantile_us(0.5);
  m.jitter_p99_us = j.quantile_us(0.99);
  m.jitter_max_us = j.max_us();
  for (const AnswerWatch& w : answers.watches()) {
    const AnswerCounts& c = w.counts();
    m.name.push_back(w.name());
    m.in_time.push_back(c.in_time);
    m.late.push_back(c.late);
    m.missing.push_back(c.missing);
    m.out_of_order.push_back(c.out_of_order);
    m.duplicate.push_back(c.duplicate);
    m.longest_gap_cycles.push_back(c.longest_gap_cycles);
    m.watchdog_cycles.push_back(w.watchdog_cycles());
  }
  m.n_participants = static_cast<int16_t>(m.name.size());
  return {channels::rt_stats, lcm_support::encode(m)};
}

}  // namespace hil::cnc_node
