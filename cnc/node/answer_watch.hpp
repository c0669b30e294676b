#pragma once
// What the CNC sees of one participant's answers over the cycles, free of
// LCM (RIG-6 real-time mode, RIG-8 faults). The answer to cycle k is due in
// cycle k: taken then it is in time; taken in a later cycle it is late (and
// still used: it is the newest the CNC has); older than one already taken it
// is out of order, the same cycle again a duplicate (neither is used). A
// cycle that ends without its answer is counted as not in time; one that
// never gets it is missing. A participant heard from neither in time nor
// late for more than its watchdog (cycles, a machine parameter) is silent:
// the CNC stops the channel with a watchdog error.
#include <cstdint>
#include <string>

namespace hil::cnc_node {

struct AnswerCounts {
  int64_t in_time = 0;
  int64_t late = 0;
  int64_t missing = 0;  // cycles whose answer never came (so far)
  int64_t out_of_order = 0;
  int64_t duplicate = 0;
  int64_t longest_gap_cycles = 0;  // the most cycles in a row without hearing from it
};

class AnswerWatch {
 public:
  AnswerWatch(std::string name, int64_t watchdog_cycles) : name_(std::move(name)), watchdog_(watchdog_cycles) {}

  enum class Answer { in_time, late, out_of_order, duplicate, future };
  // The answer to `answered_cycle`, received in cycle `now`: in_time and
  // late are to be used, the others not (a future one is refused: forged).
  Answer take(int64_t answered_cycle, int64_t now);
  // Cycle `now` has ended; `counted`: it counts towards the watchdog. True
  // once the participant has been silent for more than its watchdog.
  bool end_cycle(int64_t now, bool counted = true);

  const std::string& name() const { return name_; }
  int64_t watchdog_cycles() const { return watchdog_; }
  const AnswerCounts& counts() const { return counts_; }
  // Counted cycles since it was last heard from.
  int64_t silent_cycles() const { return silent_; }
  // All cycles since it was last heard from, at the end of cycle `now`.
  int64_t cycles_since_heard(int64_t now) const { return now - heard_in_; }
  // The newest cycle answered, -1 if none.
  int64_t newest_answered() const { return newest_; }

 private:
  std::string name_;
  int64_t watchdog_;
  AnswerCounts counts_;
  int64_t newest_ = -1;     // the newest cycle answered
  int64_t heard_in_ = -1;   // the cycle it was last heard in
  int64_t not_in_time_ = 0;  // cycles ended without their answer
  int64_t silent_ = 0;       // counted cycles ended since it was last heard
};

}  // namespace hil::cnc_node
