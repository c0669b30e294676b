#include "answer_watch.hpp"

#include <algorithm>

namespace hil::cnc_node {

AnswerWatch::Answer AnswerWatch::take(int64_t answered_cycle, int64_t now) {
  if (answered_cycle > now) return Answer::future;
  if (answered_cycle == newest_) {
    ++counts_.duplicate;
    return Answer::duplicate;
  }
  if (answered_cycle < newest_) {
    ++counts_.out_of_order;
    return Answer::out_of_order;
  }
  counts_.longest_gap_cycles = std::max(counts_.longest_gap_cycles, now - heard_in_ - 1);
  newest_ = answered_cycle;
  heard_in_ = now;
  silent_ = 0;
  if (answered_cycle == now) {
    ++counts_.in_time;
    return Answer::in_time;
  }
  ++counts_.late;
  counts_.missing = not_in_time_ - counts_.late;
  return Answer::late;
}

bool AnswerWatch::end_cycle(int64_t now, bool counted) {
  if (heard_in_ != now && counted) ++silent_;
  if (newest_ != now) {
    ++not_in_time_;
    counts_.missing = not_in_time_ - counts_.late;
    counts_.longest_gap_cycles = std::max(counts_.longest_gap_cycles, now - heard_in_);
  }
  return silent_ > watchdog_;
}

}  // namespace hil::cnc_node
