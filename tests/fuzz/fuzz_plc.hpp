#pragma once
// The channel fuzz's PLC (KRN-4): feed hold, override, delete distance to
// go, backward motion, M acknowledgements, insert stop commands and resets
// with block searches (DPS-3) at random, then calm.
#include <algorithm>
#include <cstdint>

#include "channel_fuzz.hpp"
#include "fuzz_rng.hpp"
#include "hli.hpp"

namespace hil::fuzz {

// The lowest override of the calm phase, in 0.1 %: 30 %.
constexpr int32_t calm_override_min = 300;

// The PLC of a run: a random personality (which units it plays with, how
// often, how late it acknowledges), random until `chaos_end`, calm after.
class FuzzPlc {
 public:
  // What the PLC last asked a block search for (DPS-3).
  struct SearchRequest {
    bool at_stop = false;  // type 4 at block_nr_r and dist_prog_start read at the stop (not on an approach)
    BlockSearchCommand command;
  };

  // Override values up to 120 %: above the machine's override_max_percent
  // the channel clamps them (with a warning).
  // `lines`: the program's NC lines (line i has N<10 i>): random block numbers to search.
  FuzzPlc(uint64_t seed, int64_t chaos_end, bool insert_stops, bool block_search = false, int64_t lines = 0)
      : rng_(seed), insert_rng_(seed ^ 0x15c0ffee), search_rng_(seed ^ 0x5ea4c4),
        chaos_end_(chaos_end), insert_stops_(insert_stops), block_search_(block_search), lines_(lines) {
    use_search_ = search_rng_.chance(0.35);
    search_chance_ = search_rng_.log_uniform(0.002, 0.2);
    use_insert_ = insert_rng_.chance(0.6);
    insert_mean_ = insert_rng_.log_uniform(20, 2000);
    continue_delay_max_ = insert_rng_.chance(0.5) ? 3 : 400;
    next_insert_ = 1 + static_cast<int64_t>(insert_rng_.uniform(0, 2 * insert_mean_));
    use_feedhold_ = rng_.chance(0.5);
    use_override_ = rng_.chance(0.6);
    ramp_override_ = rng_.chance(0.2);
    use_ddtg_ = rng_.chance(0.5);
    use_backward_ = rng_.chance(0.4);
    spurious_acks_ = rng_.chance(0.2);
    feedhold_mean_ = rng_.log_uniform(20, 1500);
    override_mean_ = ramp_override_ ? rng_.uniform(1, 5) : rng_.log_uniform(5, 1500);
    ddtg_mean_ = rng_.log_uniform(50, 3000);
    backward_mean_ = rng_.log_uniform(30, 2000);
    const size_t delay = rng_.pick({0.3, 0.4, 0.2, 0.1});
    ack_delay_max_ = delay == 0 ? 1 : delay == 1 ? 20 : delay == 2 ? 300 : 2000;
    calm_override_enable_ = rng_.chance(0.7);
    calm_override_ = static_cast<int32_t>(rng_.integer(calm_override_min, 1200));
    next_feedhold_ = gap(feedhold_mean_);
    next_override_ = gap(override_mean_);
    next_ddtg_ = gap(ddtg_mean_);
    next_backward_ = gap(backward_mean_);
  }

  const PlcCounts& counts() const { return counts_; }
  // The last block search asked for (DPS-3).
  const SearchRequest& last_search() const { return last_search_; }
  // The answer to the state of cycle k, applied by step k + 1.
  void answer(int64_t k, const HliState& s, HliControl& c) {
    c.cycle = k;
    c.program_start.command_w = false;
    const bool chaos = k < chaos_end_;
    if (!chaos) {
      c.feedhold = {false, true};
      c.override = {calm_override_, calm_override_enable_};
      c.delete_distance_to_go.command_w = false;
      // Forward, but a short cut running backward cannot turn (DDTG-10: it
      // stands until backward motion is requested again): let it finish.
      c.backward_motion = {s.backward_motion.state_r && s.delete_distance_to_go_active_r, true};
    }
    if (chaos && use_feedhold_ && k >= next_feedhold_) {
      c.feedhold = {!c.feedhold.command_w, rng_.chance(0.95)};
      next_feedhold_ = k + gap(feedhold_mean_);
      ++counts_.feedhold_edges;
    }
    if (chaos && use_override_ && k >= next_override_) {
      int32_t value;
      if (ramp_override_) {
        value = std::clamp(c.override.command_w + static_cast<int32_t>(rng_.integer(-40, 40)), 0, override_top_);
      } else {
        const size_t which = rng_.pick({0.15, 0.55, 0.15, 0.15});
        value = static_cast<int32_t>(which == 0   ? 0
                                     : which == 1 ? rng_.integer(0, override_top_)
                                     : which == 2 ? rng_.integer(950, 1050)
                                                  : rng_.integer(1, 50));
      }
      c.override = {value, rng_.chance(0.9)};
      next_override_ = k + gap(override_mean_);
      ++counts_.override_changes;
    }
    if (chaos && use_ddtg_) {
      ControlUnitBool& ddtg = c.delete_distance_to_go;
      if (!ddtg.command_w && k >= next_ddtg_) {
        ddtg = {true, rng_.chance(0.9)};
        const uint32_t mask = rng_.chance(0.4) ? 0u : static_cast<uint32_t>(rng_.integer(1, 15));
        c.delete_distance_to_go_activation = {mask, rng_.chance(0.85)};
        // Held: a few cycles (withdrawn before the short cut, DDTG-3), until
        // the short cut runs, or long.
        const size_t hold = rng_.pick({0.25, 0.4, 0.35});
        release_on_active_ = hold == 1;
        ddtg_release_ = k + (hold == 0 ? rng_.integer(1, 20) : hold == 1 ? 5000 : rng_.integer(50, 600));
        ++counts_.ddtg_edges;
      } else if (ddtg.command_w && (k >= ddtg_release_ || (release_on_active_ && s.delete_distance_to_go_active_r))) {
        ddtg.command_w = false;
        next_ddtg_ = k + gap(ddtg_mean_);
      }
    }
    if (chaos && use_backward_ && k >= next_backward_) {
      c.backward_motion = {!c.backward_motion.command_w, rng_.chance(0.95)};
      next_backward_ = k + gap(backward_mean_);
      ++counts_.backward_toggles;
    }
    acknowledge(k, s, c, chaos);
    if (insert_stops_) insert(k, s, c, chaos);
    if (block_search_) reset_and_search(k, s, c, chaos);
  }

  // The M function of an insert stop mark (M<n>, ISC-5).
  static constexpr int insert_m_function = 95;

 private:
  // Insert stop marks (ISC): random commands with the semaphore handshake,
  // every row of the DISTANCE and POSITION tables, M00 / M01 / M<n>, and
  // continue motion a random delay after an M00 / M01 stop. Calm: one
  // command that clears the mark, prompt continuation.
  void insert(int64_t k, const HliState& s, HliControl& c, bool chaos) {
    c.insert_cmd.semaphor_rw = s.insert_cmd.semaphor_rw;  // the CNC cleared it once read
    c.insert_cmd.enable_w = !chaos || !insert_rng_.chance(0.01);
    c.continue_motion.enable_w = true;
    if (c.continue_motion.command_w) {
      c.continue_motion.command_w = false;
    } else if (s.stop_conditions_r & (stop_condition::m0_stop | stop_condition::m1_stop)) {
      if (continue_at_ < 0) continue_at_ = k + insert_rng_.integer(0, chaos ? continue_delay_max_ : 3);
      if (k >= continue_at_) {
        c.continue_motion.command_w = true;
        continue_at_ = -1;
        ++counts_.insert_stops;
      }
    }
    if (chaos && use_insert_ && insert_rng_.chance(0.002)) c.m01_stop_enable = {insert_rng_.chance(0.5), true};
    if (!chaos && !cleared_) {
      c.m01_stop_enable = {false, true};
      if (c.insert_cmd.semaphor_rw) return;
      c.insert_cmd.command_w = {};  // DIST=0 REL: clears
      c.insert_cmd.semaphor_rw = true;
      c.insert_cmd.enable_w = true;
      cleared_ = true;
      return;
    }
    if (!chaos || !use_insert_ || k < next_insert_ || c.insert_cmd.semaphor_rw) return;
    next_insert_ = k + 1 + static_cast<int64_t>(insert_rng_.uniform(0, 2 * insert_mean_));
    InsertCmdCommand& w = c.insert_cmd.command_w;
    const size_t dist = insert_rng_.pick({0.1, 0.1, 0.3, 0.4, 0.1});
    w.dist_or_pos = dist == 0   ? 0.0
                    : dist == 1 ? -insert_rng_.uniform(0, 1e6)
                    : dist == 2 ? insert_rng_.uniform(0, 5e4)
                    : dist == 3 ? insert_rng_.uniform(0, 1e6)
                                : insert_rng_.uniform(1e6, 1e8);
    w.rel_abs_mode = static_cast<uint16_t>(insert_rng_.pick({0.35, 0.3, 0.3, 0.05}));
    w.axis_nr = insert_rng_.chance(0.7) ? 0 : static_cast<uint16_t>(insert_rng_.integer(1, 4));  // 4: no such axis
    if (w.axis_nr > 0 && w.axis_nr <= 3 && w.rel_abs_mode == 1)  // somewhere near the axis
      w.dist_or_pos = static_cast<double>(s.axis_position_r[w.axis_nr - 1]) + insert_rng_.uniform(-2e5, 2e5);
    const size_t m = insert_rng_.pick({0.5, 0.25, 0.25});
    w.m_function_nr = static_cast<uint16_t>(m == 0 ? 0 : m == 1 ? 1 : insert_m_function);
    w.add_nr = static_cast<int32_t>(insert_rng_.integer(-100, 100));
    c.insert_cmd.semaphor_rw = true;
    ++counts_.insert_commands;
  }

  // DPS-3: with the path standing under feed hold, a reset, then a block
  // search mostly at what was read at the stop (block_nr_r,
  // dist_prog_start), sometimes type 1, another distance or another block
  // (errors allowed), and a program start; a search that failed (state 3,
  // the channel READY) is followed by a start without a search. Calm: a
  // channel left READY is started. program_start.command_w is false at the
  // top of answer(): an edge needs the cycle before it false.
  void reset_and_search(int64_t k, const HliState& s, HliControl& c, bool chaos) {
    c.reset.enable_w = true;
    c.reset.command_w = false;
    const bool start_edge_possible = k > last_start_ + 1;  // the answer after an edge's is false
    auto start = [&](bool search) {
      c.block_search.enable_w = search;
      c.program_start = {true, true};
      last_start_ = k;
    };
    switch (search_phase_) {
      case SearchPhase::idle:
        if (chaos && use_search_ && resets_given_ < 3 && s.channel_state == ChannelState::active &&
            s.path_velocity == 0 && s.feedhold.state_r && search_rng_.chance(search_chance_)) {
          stop_block_nr_ = s.block_nr_r;
          stop_distance_ = s.dist_prog_start;
          // Standing on an approach, dist_prog_start shows the continuation's distance, not where the path stands.
          read_on_approach_ = s.block_search.state_r.state == block_search_state::repositioning;
          c.reset = {true, true};
          ++resets_given_;
          search_phase_ = SearchPhase::reset_given;
        } else if (!chaos && s.channel_state == ChannelState::ready && start_edge_possible) {
          start(false);  // calm: a channel left READY after a reset runs the program
        }
        return;
      case SearchPhase::reset_given:
        if (s.channel_state != ChannelState::ready) {  // ignored: the path moved (a warning)
          search_phase_ = SearchPhase::idle;
          return;
        }
        if (s.reset.state_r) ++counts_.resets;
        if (!start_edge_possible) return;
        {
          const size_t which = search_rng_.pick({0.7, 0.1, 0.1, 0.1});
          BlockSearchCommand& w = c.block_search.command_w;
          w.type = which == 1 ? 1 : 4;
          w.block_nr = static_cast<uint32_t>(which == 3 ? 10 * search_rng_.integer(1, lines_ + 1) : stop_block_nr_);
          w.distance = which == 2 ? search_rng_.uniform(0, 1.5 * stop_distance_) : stop_distance_;
          last_search_.at_stop = which == 0 && !read_on_approach_;
          last_search_.command = w;
        }
        start(true);
        ++counts_.searches;
        search_phase_ = SearchPhase::search_started;
        return;
      case SearchPhase::search_started:
        c.block_search.enable_w = false;
        if (s.block_search.state_r.state == block_search_state::error) {
          ++counts_.search_errors;
          search_phase_ = SearchPhase::start_after_error;
        } else {
          search_phase_ = SearchPhase::idle;
        }
        return;
      case SearchPhase::start_after_error:
        if (!start_edge_possible) return;
        start(false);  // from the program's start, where the axes stand
        search_phase_ = SearchPhase::idle;
        return;
    }
  }

  // A rising edge of m_function_ack.command_w (one cycle long) a random
  // delay after m_function_request_r shows; a request still shown after an
  // edge is a new one (or the old one, if the edge came without enable_w).
  void acknowledge(int64_t k, const HliState& s, HliControl& c, bool chaos) {
    ControlUnitBool& ack = c.m_function_ack;
    if (ack.command_w) {
      ack.command_w = false;
    } else if (ack_at_ >= 0 && k >= ack_at_) {
      ack = {true, !(chaos && rng_.chance(0.05))};
      ack_at_ = -1;
      ++counts_.m_acks;
    } else if (chaos && spurious_acks_ && ack_at_ < 0 && rng_.chance(0.002)) {
      ack = {true, true};  // unasked: ignored, or an early acknowledgement
    } else {
      ack.enable_w = true;
    }
    if (!ack.command_w && ack_at_ < 0 && s.m_function_request_r)
      ack_at_ = k + 1 + (chaos ? rng_.integer(0, ack_delay_max_) : rng_.integer(0, 5));
    // T, S and H functions come only from a program given to the fuzz
    // (`--program`, a corpus program's T6 M06 / S14000): acknowledged the
    // cycle after their request, drawing nothing from the seed's stream, so
    // that generated programs run as before. Unacknowledged, such a program
    // waited for them until its cycle bound.
    acknowledge_at_once(s.t_function_request_r, c.t_function_ack);
    acknowledge_at_once(s.s_function_request_r, c.s_function_ack);
    acknowledge_at_once(s.h_function_request_r, c.h_function_ack);
  }

  static void acknowledge_at_once(bool request, ControlUnitBool& ack) {
    if (ack.command_w) ack.command_w = false;
    else if (request) ack = {true, true};
  }

  int64_t gap(double mean) { return 1 + static_cast<int64_t>(rng_.uniform(0, 2 * mean)); }

  Rng rng_;
  Rng insert_rng_;
  Rng search_rng_;
  int64_t chaos_end_;
  bool insert_stops_;
  bool block_search_;
  int64_t lines_;
  enum class SearchPhase { idle, reset_given, search_started, start_after_error };
  SearchPhase search_phase_ = SearchPhase::idle;
  bool use_search_ = false;
  double search_chance_ = 0;
  int resets_given_ = 0;
  int64_t last_start_ = 0;  // the answer that gave the last start edge (cycle 0's start is before answer 0)
  int64_t stop_block_nr_ = 0;
  double stop_distance_ = 0;
  bool read_on_approach_ = false;
  SearchRequest last_search_;
  bool use_insert_ = false, cleared_ = false;
  double insert_mean_ = 0;
  int64_t continue_delay_max_ = 3, next_insert_ = 0, continue_at_ = -1;
  int32_t override_top_ = 1200;
  bool use_feedhold_, use_override_, ramp_override_, use_ddtg_, use_backward_, spurious_acks_;
  double feedhold_mean_, override_mean_, ddtg_mean_, backward_mean_;
  int64_t ack_delay_max_;
  bool calm_override_enable_;
  int32_t calm_override_;
  int64_t next_feedhold_, next_override_, next_ddtg_, next_backward_;
  int64_t ddtg_release_ = 0;
  bool release_on_active_ = false;
  int64_t ack_at_ = -1;
  PlcCounts counts_;
};

}  // namespace hil::fuzz
