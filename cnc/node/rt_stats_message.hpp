#pragma once
// RIG-6 real-time mode: the CNC's figures so far as an HIL_RT_STATS message
// (rt_stats_t): the tick's jitter and overruns, each participant's answers.
#include <cstdint>
#include <string>

#include "cycle_messages.hpp"
#include "real_time_answers.hpp"
#include "tick_clock.hpp"

namespace hil::cnc_node {

// Every this many cycles, and once more, final, before the RUN_END.
constexpr int64_t rt_stats_every_cycles = 1000;

EncodedMessage rt_stats_message(const Ticker& ticker, const RealTimeAnswers& answers, const std::string& scheduling,
                                int64_t cycle, int32_t cycle_us, int64_t run_id, bool final);

}  // namespace hil::cnc_node
