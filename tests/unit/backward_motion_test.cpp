// KRN-5 backward motion on the path, and DDTG-10 (delete distance to go
// and backward motion), cycle by cycle; every run goes through the offline
// limit checker.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "channel_runner.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

struct Sample {
  int64_t cycle;
  double x, y, dps;
  bool backward, active;
  int64_t block_nr;
};

struct Run {
  std::vector<Sample> samples;
  std::vector<Event> events;
  bool has(int32_t id) const {
    for (const Event& e : events)
      if (e.id == id) return true;
    return false;
  }
  const Sample& end() const { return samples.back(); }
};

// `plc` decides the PLC's answer from the samples so far.
Run run(const std::string& program, const std::function<void(const Run&, HliControl&)>& plc,
        int64_t fb_storage_size = 1000000) {
  MachineConfig m = test::xyz_machine();
  m.fb_storage_size = fb_storage_size;
  Channel channel(m, program);
  logger::LimitChecker checker(m);
  Run r;
  test::run_program(channel, &checker, [&](int64_t k, const HliState& s, HliControl& c) {
    r.samples.push_back({k, channel.setpoints()[0].position, channel.setpoints()[1].position,
                         s.dist_prog_start / hli_units_per_mm, s.backward_motion.state_r,
                         s.delete_distance_to_go_active_r, s.block_nr_r});
    for (Event& e : channel.take_events()) r.events.push_back(e);
    c.backward_motion.enable_w = true;
    c.delete_distance_to_go.enable_w = true;
    c.m_function_ack = {s.m_function_request_r && !c.m_function_ack.command_w, true};
    plc(r, c);
  }, 0, 200000);
  const HliState& end = channel.hli();
  r.samples.push_back({end.cycle, channel.setpoints()[0].position, channel.setpoints()[1].position,
                       end.dist_prog_start / hli_units_per_mm, end.backward_motion.state_r,
                       end.delete_distance_to_go_active_r, end.block_nr_r});
  for (const auto& v : checker.finish().violations)
    FAIL_CHECK(v.axis << " " << v.quantity << " " << v.value << " > " << v.limit << " at " << v.time_s);
  return r;
}

const std::string square = "N10 G1 X50 F3000\nN20 Y50\nN30 X0 M7\nN40 Y0\nM30\n";

}  // namespace

TEST_CASE("KRN-5 backward motion runs back along the programmed contour, forward again, and on to the end",
          "[backward]") {
  int64_t m7 = 0;
  bool went_back_into_n20 = false;
  const Run r = run(square, [&](const Run& r, HliControl& c) {
    const Sample& s = r.samples.back();
    if (s.block_nr == 30 && s.x < 25 && !went_back_into_n20) c.backward_motion.command_w = true;
    if (s.backward && s.block_nr == 20 && s.y < 30) {
      went_back_into_n20 = true;
      c.backward_motion.command_w = false;
    }
    if (c.m_function_ack.command_w) ++m7;
  });
  bool backward_seen = false;
  double lowest_y_in_n20 = 100, dps_at_turn = 0;
  for (const Sample& s : r.samples) {
    if (s.backward) backward_seen = true;
    if (s.block_nr == 20) {
      CHECK(s.x == Approx(50).margin(1e-9));  // on the programmed contour, both ways
      if (backward_seen) lowest_y_in_n20 = std::min(lowest_y_in_n20, s.y);
    }
    if (s.block_nr == 30) CHECK(s.y == Approx(50).margin(1e-9));
    if (s.backward) dps_at_turn = s.dps;
  }
  CHECK(backward_seen);
  CHECK(lowest_y_in_n20 < 30);
  CHECK(lowest_y_in_n20 > 20);  // stopped soon after the request was taken back
  CHECK(dps_at_turn == Approx(50 + lowest_y_in_n20).margin(0.5));  // dist_prog_start counts back too
  CHECK(m7 == 1);  // M7 of N30 is not output again when the path runs N30 a second time
  CHECK(r.end().x == Approx(0).margin(1e-9));
  CHECK(r.end().y == Approx(0).margin(1e-9));
  CHECK(r.end().dps == Approx(200).margin(1e-6));
}

TEST_CASE("KRN-5 backward motion stands at the start of the stored contour: program start or P-STUP-00033 full",
          "[backward]") {
  for (const int64_t storage : {int64_t{1000000}, static_cast<int64_t>(2 * sizeof(Block))}) {
    INFO("fb_storage_size " << storage);
    bool requested = false;
    int64_t stood_since = -1;
    const Run r = run(square, [&](const Run& r, HliControl& c) {
      const Sample& s = r.samples.back();
      if (s.block_nr == 40 && s.y < 25) requested = true;
      for (const Event& e : r.events)
        if (stood_since < 0 && e.message.find("start of the stored contour") != std::string::npos) stood_since = s.cycle;
      c.backward_motion.command_w = requested && (stood_since < 0 || s.cycle < stood_since + 200);
    }, storage);
    REQUIRE(stood_since > 0);
    const Sample* at_start = nullptr;
    for (const Sample& s : r.samples)
      if (s.cycle == stood_since + 100) at_start = &s;
    REQUIRE(at_start != nullptr);
    if (storage == 1000000) {  // back to the program start
      CHECK(at_start->x == Approx(0).margin(1e-9));
      CHECK(at_start->y == Approx(0).margin(1e-9));
      CHECK(at_start->dps == Approx(0).margin(1e-6));
    } else {  // two blocks stored below the furthest (N40): N30 and N40 back to N30's start
      CHECK(at_start->x == Approx(50).margin(1e-9));
      CHECK(at_start->y == Approx(50).margin(1e-9));
    }
    CHECK(r.end().x == Approx(0).margin(1e-9));  // forward again to the program end
    CHECK(r.end().y == Approx(0).margin(1e-9));
  }
}

TEST_CASE("DDTG-10 backward motion after a short cut follows the original contour, not the short cut",
          "[backward][ddtg]") {
  // TF5200_delete_distance_to_go.txt 2.7, Fig. 16.
  bool cut_done = false, back_in_n10 = false;
  const Run r = run("N10 G1 X80 F3000\nN20 Y60\nN30 X0\nM30\n", [&](const Run& r, HliControl& c) {
    const Sample& s = r.samples.back();
    c.delete_distance_to_go.command_w = s.cycle >= 500 && !s.active && !cut_done;
    if (s.active) cut_done = true;
    if (s.block_nr == 30 && s.x < 60) c.backward_motion.command_w = true;
    if (s.backward && s.block_nr == 10) back_in_n10 = true;
    if (back_in_n10 && s.x < 60) c.backward_motion.command_w = false;
    if (!s.backward && back_in_n10) c.backward_motion.command_w = false;
  });
  REQUIRE(cut_done);
  bool on_n20_backward = false;
  for (const Sample& s : r.samples)
    if (s.backward && s.block_nr == 20) {
      on_n20_backward = true;
      CHECK(s.x == Approx(80).margin(1e-9));  // N20 as programmed, X80, not the short cut's diagonal
    }
  CHECK(on_n20_backward);
  CHECK(back_in_n10);
  CHECK(r.end().x == Approx(0).margin(1e-9));
  CHECK(r.end().y == Approx(60).margin(1e-9));
}

TEST_CASE("DDTG-10 delete distance to go in backward motion short-cuts backward; no reversal on it (50729)",
          "[backward][ddtg]") {
  // TF5200_delete_distance_to_go.txt 2.7 (Fig. 17) and 4.7: backward in N30,
  // DDTG: a short cut to the start of N20 (50, 0); forward requested on it
  // is held with 50729 until backward is requested again.
  enum { forward, backward, ddtg, refused, back_again, at_start, done } phase = forward;
  int64_t refused_at = 0;
  double held_x = 0, held_y = 0;
  bool moved_while_refused = false;
  const Run r = run(square, [&](const Run& r, HliControl& c) {
    const Sample& s = r.samples.back();
    switch (phase) {
      case forward: if (s.block_nr == 30 && s.x < 20) phase = backward; break;
      case backward: if (s.backward && s.x > 30) phase = ddtg; break;
      case ddtg: if (s.active) phase = refused, refused_at = s.cycle; break;
      case refused:
        if (s.cycle == refused_at + 150) held_x = s.x, held_y = s.y;
        if (s.cycle > refused_at + 150) moved_while_refused = moved_while_refused || s.x != held_x || s.y != held_y;
        if (s.cycle > refused_at + 1000) phase = back_again;
        break;
      case back_again: if (!s.active && s.block_nr == 10) phase = at_start; break;
      case at_start: if (s.x == 0 && s.y == 0) phase = done; break;  // back along N10 to the program start
      case done: break;
    }
    c.backward_motion.command_w = phase != forward && phase != refused && phase != done;
    c.delete_distance_to_go.command_w = phase == ddtg;
  });
  CHECK(phase == done);
  CHECK(r.has(50729));
  CHECK_FALSE(moved_while_refused);
  bool cut_seen = false;
  const Sample* first_cut = nullptr;
  for (const Sample& s : r.samples)
    if (s.active && s.backward) {
      if (!first_cut) first_cut = &s;
      cut_seen = true;
      CHECK(s.block_nr == 20);
    }
  REQUIRE(cut_seen);
  // Linear from the stop in N30 (y = 50) to N20's start (50, 0).
  for (const Sample& s : r.samples)
    if (s.active && s.backward) {
      const double ax = first_cut->x, ay = first_cut->y;
      CHECK(std::abs((50 - ax) * (s.y - ay) - (0 - ay) * (s.x - ax)) / std::hypot(50 - ax, ay) < 1e-6);
    }
  CHECK(r.end().x == Approx(0).margin(1e-9));
  CHECK(r.end().y == Approx(0).margin(1e-9));
}

TEST_CASE("KRN-5 backward requested at the program start: the path stands there; withdrawn, the program runs",
          "[backward]") {
  // The request reaches the CNC one cycle after the start: the path has
  // begun to move, stops within micrometres and goes back to the start.
  const Run r = run(square, [&](const Run& r, HliControl& c) { c.backward_motion.command_w = r.samples.size() < 300; });
  for (const Sample& s : r.samples)
    if (s.cycle < 300) {
      CHECK(s.x >= 0);
      CHECK(s.x < 0.001);
      CHECK(s.y == 0);
    }
  CHECK(r.samples.at(290).x == 0);
  bool warned = false;
  for (const Event& e : r.events) warned = warned || e.message.find("stored contour") != std::string::npos;
  CHECK(warned);
  CHECK(r.end().x == Approx(0).margin(1e-9));
  CHECK(r.end().y == Approx(0).margin(1e-9));
  CHECK(r.end().dps == Approx(200).margin(1e-6));
}

TEST_CASE("KRN-5 without P-STUP-00033 a backward request only holds the path, with a warning", "[backward]") {
  const Run r = run(square, [&](const Run& r, HliControl& c) {
    const Sample& s = r.samples.back();
    c.backward_motion.command_w = s.block_nr == 20 && s.cycle < 3000;
  }, 0);
  bool warned = false;
  for (const Event& e : r.events) warned = warned || e.parameter == "P-STUP-00033";
  CHECK(warned);
  for (const Sample& s : r.samples) CHECK_FALSE(s.backward);
  CHECK(r.end().dps == Approx(200).margin(1e-6));
}

TEST_CASE("KRN-5 a backward request while the program's last M function waits: the program still ends there",
          "[backward]") {
  int waited = 0;
  const Run r = run("N10 G1 X50 F3000\nN20 M7\nM30\n", [&](const Run& r, HliControl& c) {
    const Sample& s = r.samples.back();
    c.backward_motion.command_w = s.x == 50;
    if (++waited < 3000) c.m_function_ack.command_w = false;  // acknowledged late
  });
  for (const Sample& s : r.samples) CHECK(s.x <= 50);
  CHECK(r.end().x == Approx(50).margin(1e-9));
  CHECK(r.samples.size() < 10000);  // it ended
}
