#include "advanced_lifting.hpp"

#include <algorithm>
#include <cmath>

#include "position_profile.hpp"
#include "tolerances.hpp"

namespace hil::cnc {

AdvancedLifting::AdvancedLifting(double z0, double pos, double peak, const Limits& lim, double cycle_s)
    : state_{z0, 0, 0, 0}, pos_(pos), peak_(peak), lim_(lim), cycle_s_(cycle_s) {}

const MotionState& AdvancedLifting::step(double earliest_end_s) {
  if (!lowering_) {
    const MotionState next = position_profile(state_, peak_, lim_, SlopeType::trapez).at(cycle_s_);
    const double landing = position_profile(next, pos_, lim_, SlopeType::trapez).duration();
    if (landing + cycle_s_ <= earliest_end_s) {
      state_ = next;
      // On POS at rest as its summit (POS at or beyond POS_LIMIT): landed.
      if (peak_ == pos_ && std::abs(state_.p - pos_) <= tolerance::same_point_share * (1 + std::abs(pos_)) &&
          std::abs(state_.v) <= tolerance::velocity_mm_s && std::abs(state_.a) <= tolerance::acceleration_mm_s2)
        land_now();
      return state_;
    }
    land_now();
  }
  since_lowering_ += cycle_s_;
  state_ = fall_.at(since_lowering_);
  if (landed()) state_ = MotionState{pos_, 0, 0, 0};
  return state_;
}

double AdvancedLifting::landing_s() const {
  return lowering_ ? std::max(fall_.duration() - since_lowering_, 0.0)
                   : position_profile(state_, pos_, lim_, SlopeType::trapez).duration();
}

void AdvancedLifting::land_now() {
  if (lowering_) return;
  lowering_ = true;
  fall_ = position_profile(state_, pos_, lim_, SlopeType::trapez);
  since_lowering_ = 0;
}

}  // namespace hil::cnc
