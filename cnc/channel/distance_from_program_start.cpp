#include "distance_from_program_start.hpp"

namespace hil::cnc {

void DistanceFromProgramStart::apply(DistanceProgStart command) {
  switch (command) {
    case DistanceProgStart::on: counting_ = true; break;
    case DistanceProgStart::off: counting_ = false; break;
    case DistanceProgStart::clear: before_front_ = 0; break;
  }
}

void DistanceFromProgramStart::command(DistanceProgStart command, uint64_t after, uint64_t done) {
  if (waiting_.empty() && done >= after) apply(command);
  else waiting_.emplace_back(after, command);
}

void DistanceFromProgramStart::actions_done(uint64_t done) {
  for (; !waiting_.empty() && waiting_.front().first <= done; waiting_.pop_front()) apply(waiting_.front().second);
}

}  // namespace hil::cnc
