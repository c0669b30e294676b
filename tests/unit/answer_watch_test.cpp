// RIG-6 (real-time mode) and RIG-8 (faults): how the CNC counts a
// participant's answers over the cycles, and when its watchdog fires.
#include <catch2/catch.hpp>

#include "answer_watch.hpp"

using hil::cnc_node::AnswerWatch;
using Answer = AnswerWatch::Answer;

TEST_CASE("RIG-6 RIG-8 answer watch: in time, late, out of order, duplicate, missing, the longest gap", "[RIG-6][RIG-8]") {
  AnswerWatch w("axis_sim X", 20);
  CHECK(w.take(0, 0) == Answer::in_time);
  CHECK_FALSE(w.end_cycle(0));
  CHECK(w.take(1, 1) == Answer::in_time);
  CHECK(w.take(1, 1) == Answer::duplicate);
  CHECK_FALSE(w.end_cycle(1));
  // cycles 2 and 3 end without their answers; the answer to 3 comes in 4
  CHECK_FALSE(w.end_cycle(2));
  CHECK_FALSE(w.end_cycle(3));
  CHECK(w.counts().missing == 2);
  CHECK(w.take(3, 4) == Answer::late);
  CHECK(w.take(2, 4) == Answer::out_of_order);  // older than the one taken: not used
  CHECK(w.take(5, 4) == Answer::future);
  CHECK_FALSE(w.end_cycle(4));
  const auto& c = w.counts();
  CHECK(c.in_time == 2);
  CHECK(c.late == 1);
  CHECK(c.missing == 2);  // the answers to 2 and 4 have not come; 3's came late
  CHECK(c.out_of_order == 1);
  CHECK(c.duplicate == 1);
  CHECK(c.longest_gap_cycles == 2);  // nothing heard in cycles 2 and 3
  CHECK(w.newest_answered() == 3);
}

TEST_CASE("RIG-6 RIG-8 answer watch: silent for more than the watchdog's cycles, and not before", "[RIG-6][RIG-8]") {
  AnswerWatch w("plc_sim", 20);
  CHECK(w.take(0, 0) == Answer::in_time);
  CHECK_FALSE(w.end_cycle(0));
  for (int64_t k = 1; k <= 20; ++k) CHECK_FALSE(w.end_cycle(k));  // silent 20 cycles: within the watchdog
  CHECK(w.silent_cycles() == 20);
  CHECK(w.end_cycle(21));  // the 21st
  CHECK(w.counts().missing == 21);
  CHECK(w.counts().longest_gap_cycles == 21);
  // one late answer resets the silence
  CHECK(w.take(21, 22) == Answer::late);
  CHECK_FALSE(w.end_cycle(22));
  CHECK(w.silent_cycles() == 0);
}

TEST_CASE("RIG-6 answer watch: a cycle that does not count (the CNC ran it late) leaves the watchdog where it was",
          "[RIG-6]") {
  AnswerWatch w("axis_sim X", 20);
  CHECK(w.take(0, 0) == Answer::in_time);
  CHECK_FALSE(w.end_cycle(0));
  for (int64_t k = 1; k <= 10; ++k) CHECK_FALSE(w.end_cycle(k));
  for (int64_t k = 11; k <= 60; ++k) CHECK_FALSE(w.end_cycle(k, false));  // a host stall of 50 cycles
  CHECK(w.silent_cycles() == 10);
  CHECK(w.cycles_since_heard(60) == 60);
  CHECK(w.counts().missing == 60);  // counted as missing all the same
  for (int64_t k = 61; k <= 70; ++k) CHECK_FALSE(w.end_cycle(k));
  CHECK(w.end_cycle(71));  // the 21st cycle it had the time to answer in
}
