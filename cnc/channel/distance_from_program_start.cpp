#include "distance_from_program_start.hpp"

namespace hil::cnc {

void DistanceFromProgramStart::apply(DistanceProgStart command) {
  switch (command) {
    case DistanceProgStart::on: counting_ = true; break;
    case DistanceProgStart::off: counting_ = false; break;
    case DistanceProgStart::clear: before_front_ = 0; break;
  }
}

}  // namespace hil::cnc
