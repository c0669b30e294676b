// RIG-8: a drive whose setpoints are lost on the way bridges the gap at the
// last commanded velocity (as in interpolated position mode) and answers
// the next setpoint it gets; a setpoint further ahead than its watchdog
// allows is refused as forged.
#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>

#include <catch2/catch.hpp>
#include <vector>

#include "axis_sim_node.hpp"
#include "channels.hpp"
#include "in_process_bus.hpp"
#include "inbox.hpp"

using namespace hil;

namespace {

struct Drive {
  AxisConfig axis;
  lcm_support::InProcessBus bus;
  lcm_support::Inbox inbox{bus, 7};
  axis::AxisSimNode node;
  std::vector<hil::axis_state_t> answers;

  explicit Drive(const AxisConfig& a) : axis(a), node(a, 0.001, inbox) {
    bus.subscribe(
        channels::axis_state("X"),
        [this](const lcm::ReceiveBuffer& rbuf, const std::string&) {
          hil::axis_state_t s;
          REQUIRE(lcm_support::decode(rbuf.data, rbuf.data_size, s));
          answers.push_back(s);
        },
        1000);
  }
  void setpoint(int64_t cycle, double position, double velocity) {
    hil::axis_setpoint_t m{};
    m.run_id = 7;
    m.cycle = cycle;
    m.utime = cycle * 1000;
    m.axis = "X";
    m.position = position;
    m.velocity = velocity;
    static_cast<lcm_support::Bus&>(bus).publish(channels::axis_command("X"), m);
    bus.drain();
  }
};

AxisConfig axis_x() {
  AxisConfig a;
  a.name = "X";
  a.v_max = 250;
  a.v_rapid = 250;
  a.a_max = 2000;
  a.j_max = 40000;
  a.kv = 40;
  a.velocity_lag_s = 0.002;
  a.watchdog_cycles = 20;
  return a;
}

}  // namespace

TEST_CASE("RIG-8 a drive bridges lost setpoints at the last velocity, and refuses a jump beyond its watchdog",
          "[RIG-8][drive]") {
  // Two drives on the same setpoints at 100 mm/s; one loses cycles 300..309.
  Drive whole(axis_x()), gapped(axis_x());
  const double v = 100, dt = 0.001;
  for (int64_t k = 0; k < 400; ++k) {
    const double p = v * dt * static_cast<double>(k);
    whole.setpoint(k, p, k == 0 ? 0 : v);
    if (k < 300 || k >= 310) gapped.setpoint(k, p, k == 0 ? 0 : v);
  }
  REQUIRE(whole.answers.size() == 400);
  REQUIRE(gapped.answers.size() == 390);  // no answer to what it did not get
  CHECK(gapped.answers[300].cycle == 310);
  // Bridged at constant velocity on a constant-velocity path: the same motion.
  CHECK(gapped.answers.back().position == Approx(whole.answers.back().position).margin(1e-9));
  CHECK(gapped.answers[300].following_error == Approx(whole.answers[310].following_error).margin(1e-9));

  // 20 cycles of watchdog: cycle 399 + 1 + 20 is the furthest it takes.
  gapped.setpoint(399 + 22, 0, 0);
  CHECK(gapped.answers.size() == 390);
  CHECK(gapped.node.last_cycle() == 399);
  gapped.setpoint(399 + 21, 39.9 + 21 * v * dt, v);
  CHECK(gapped.answers.size() == 391);
  CHECK(gapped.node.last_cycle() == 420);
  // Old and repeated cycles are refused.
  gapped.setpoint(420, 0, 0);
  gapped.setpoint(100, 0, 0);
  CHECK(gapped.answers.size() == 391);
}
