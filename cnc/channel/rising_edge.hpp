#pragma once
// The edge memory of a control unit's command_w (KRN-4): units that act on
// a rising edge, not on the level, remember the last cycle's command.
namespace hil::cnc {

class RisingEdge {
 public:
  // True in the cycle command_w goes from FALSE to TRUE.
  bool operator()(bool command_w) {
    const bool rising = command_w && !previous_;
    previous_ = command_w;
    return rising;
  }

 private:
  bool previous_ = false;
};

}  // namespace hil::cnc
