// The lift function's planning without the channel (TF5200_lift_function.txt):
// the profile planned in advance (LIFT-3, LIFT-4), Advanced Lifting's
// real-time part (LIFT-2), the path preparation of lift ranges (LIFT-1,
// LIFT-3, LIFT-5).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "advanced_lifting.hpp"
#include "lift_profile.hpp"
#include "lift_limits.hpp"
#include "lift_ranges.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

// Largest |a| and |j| of positions sampled every dt, by differences.
struct Peaks {
  double v = 0, a = 0, j = 0;
};
Peaks peaks_of(const std::vector<double>& p, double dt) {
  Peaks out;
  for (size_t k = 1; k < p.size(); ++k) out.v = std::max(out.v, std::abs(p[k] - p[k - 1]) / dt);
  for (size_t k = 2; k < p.size(); ++k) out.a = std::max(out.a, std::abs(p[k] - 2 * p[k - 1] + p[k - 2]) / (dt * dt));
  for (size_t k = 3; k < p.size(); ++k)
    out.j = std::max(out.j, std::abs(p[k] - 3 * p[k - 1] + 3 * p[k - 2] - p[k - 3]) / (dt * dt * dt));
  return out;
}

Block line(std::vector<double> from, std::vector<double> to, double feed) {
  Block b;
  b.has_motion = true;
  b.motion.start = std::move(from);
  b.motion.end = std::move(to);
  b.motion.feed = feed;
  return b;
}

}  // namespace

TEST_CASE("LIFT-3 LIFT-4: the planned lift rises as high as its time allows and lands on POS", "[lift]") {
  const Limits lim{150, 1500, 30000};
  SECTION("ample time: the summit is the peak, reached at once, landing at the end") {
    const LiftProfile p = LiftProfile::plan(10, 12, 30, 2.0, lim);
    CHECK(p.summit() == Approx(30));
    CHECK(p.duration() == Approx(2.0));
    CHECK(p.at(2.0).p == Approx(12));
    CHECK(p.at(1.0).p == Approx(30));
  }
  SECTION("short time: the highest summit whose rise and fall fit") {
    const LiftProfile p = LiftProfile::plan(10, 12, 100, 0.3, lim);
    CHECK(p.summit() > 12);
    CHECK(p.summit() < 100);
    CHECK(positioning_time(10, p.summit(), lim) + positioning_time(p.summit(), 12, lim) == Approx(0.3).margin(1e-9));
    CHECK(p.duration() == Approx(0.3));
  }
  SECTION("too short even for the direct move: the direct move, longer than asked") {
    const LiftProfile p = LiftProfile::plan(10, 40, 50, 0.01, lim);
    CHECK(p.summit() == Approx(40));
    CHECK(p.duration() == Approx(positioning_time(10, 40, lim)));
  }
  SECTION("LIFT-2 DOWN: a lowering is the mirror") {
    const LiftProfile p = LiftProfile::plan(10, 8, -20, 2.0, lim);
    CHECK(p.summit() == Approx(-20));
    CHECK(p.at(2.0).p == Approx(8));
  }
  SECTION("LIFT-5 POS beyond POS_LIMIT: the target is reached at the start, the limit has no effect") {
    const LiftProfile p = LiftProfile::plan(10, 40, 30, 2.0, lim);
    CHECK(p.summit() == Approx(40));
    CHECK(p.at(positioning_time(10, 40, lim)).p == Approx(40));
    CHECK(p.at(2.0).p == Approx(40));
  }
  SECTION("its largest speed is the profile's, also where it peaks inside a phase") {
    // Fuzz lift seed 13010605: 7.33 -> 18.35 mm with a_max 1500, j_max
    // 15,000: no cruise, the acceleration runs from +a to -a in one phase;
    // phase ends alone said 38.5 mm/s of 76 mm/s, and Lifting's caps, sized
    // by it, let the lift axis reach 1.008 j_max.
    const Limits lifting{150, 1500, 15000};
    for (const double to : {18.348022789, 40.0, 10.5}) {
      const LiftProfile p = LiftProfile::plan(7.328456424, to, to, 0.82288, lifting);
      double sampled = 0;
      for (double tau = 0; tau <= p.duration(); tau += 1e-5) sampled = std::max(sampled, std::abs(p.at(tau).v));
      INFO("to " << to);
      CHECK(p.max_speed() >= sampled);
      CHECK(p.max_speed() == Approx(sampled).epsilon(1e-6));
    }
  }
}

TEST_CASE("LIFT-2 Advanced Lifting lands on POS by the time the path can reach the end, within the overload range",
          "[lift]") {
  const AxisConfig z = test::xyz_machine().axes[2];
  const Limits lim = advanced_lifting_limits(z, 0.001);
  CHECK(lim.a < z.a_max * z.dyn_monitoring_a_err / 1000.0);
  CHECK(lim.j == z.j_max);
  const double dt = 0.001;
  auto run = [&](double length, double v_path, double peak, double pos = 12) {
    AdvancedLifting lift(10, pos, peak, lim, dt);
    std::vector<double> trace{10};
    double rest = length;
    int cycles = 0;
    while (rest > 0 && cycles < 100000) {
      trace.push_back(lift.step(rest / v_path).p);
      rest -= v_path * dt;
      ++cycles;
    }
    for (int k = 0; k < 5; ++k) trace.push_back(lift.step(0).p);  // standing at the end
    return trace;
  };
  SECTION("a long range: up to the peak, down on time") {
    const std::vector<double> trace = run(200, 100, 30);  // 2 s of path
    CHECK(*std::max_element(trace.begin(), trace.end()) == Approx(30));
    CHECK(trace.back() == Approx(12).margin(1e-9));
    const Peaks pk = peaks_of(trace, dt);
    CHECK(pk.a <= lim.a * (1 + 1e-6));
    CHECK(pk.a > z.a_max);  // it uses the overload range
    CHECK(pk.j <= lim.j * (1 + 1e-6));
    CHECK(pk.v <= lim.v * (1 + 1e-6));
  }
  SECTION("a short range: as high as the time allows, landing when the path arrives") {
    const std::vector<double> trace = run(30, 100, 100);  // 0.3 s of path
    const double summit = *std::max_element(trace.begin(), trace.end());
    const LiftProfile best = LiftProfile::plan(10, 12, 100, 0.3, lim);
    // At least as high as the best plan that stops at its summit: turning
    // back without stopping there gains height.
    CHECK(summit >= best.summit() - 1e-3);
    // Landed within the path's 300 cycles.
    CHECK(std::abs(trace[301] - 12) < 1e-9);
    CHECK(peaks_of(trace, dt).a <= lim.a * (1 + 1e-6));
  }
  SECTION("the path waits (earliest end infinite): it holds the summit, then lands once the path can arrive") {
    AdvancedLifting lift(10, 12, 30, lim, dt);
    for (int k = 0; k < 1000; ++k) lift.step(std::numeric_limits<double>::infinity());
    CHECK(lift.state().p == Approx(30));
    CHECK_FALSE(lift.lowering());
  }
}

TEST_CASE("LIFT-1 LIFT-3 LIFT-5: the path preparation finds the ranges and caps the path in them", "[lift]") {
  MachineConfig m = test::xyz_machine();
  const std::vector<double> origin{0, 0, 10};
  auto range_blocks = [](int motions) {
    std::vector<Block> blocks;
    Block start;
    start.lift_start = LiftStart{2, false, 12, 30};
    blocks.push_back(start);
    for (int i = 0; i < motions; ++i)
      blocks.push_back(line({10.0 * i, 0, 10}, {10.0 * (i + 1), 0, 10}, 100));
    Block end;
    end.lift_end = true;
    blocks.push_back(end);
    blocks.push_back(line({10.0 * motions, 0, 12}, {10.0 * motions + 5, 0, 12}, 100));
    return blocks;
  };
  SECTION("no lift method: no ranges") {
    std::vector<Block> blocks = range_blocks(3);
    CHECK(prepare_lift_ranges(blocks, m, origin).empty());
  }
  SECTION("Lifting: one range, its length, the summit, the path capped") {
    m.lift_method = LiftMethod::path_based;
    std::vector<Block> blocks = range_blocks(3);
    const std::vector<LiftRange> ranges = prepare_lift_ranges(blocks, m, origin);
    REQUIRE(ranges.size() == 1);
    CHECK(ranges[0].start == 0);
    CHECK(ranges[0].end == 4);
    CHECK(ranges[0].length == Approx(30));
    CHECK(ranges[0].z0 == Approx(10));
    CHECK(ranges[0].peak == Approx(30));
    CHECK(ranges[0].internal_blocks == 3);
    CHECK(ranges[0].profile.at(ranges[0].profile.duration()).p == Approx(12));
    CHECK(blocks[1].motion.path_caps.v <= 100 + 1e-9);
    CHECK(std::isfinite(blocks[1].motion.path_caps.a));
    CHECK(std::isinf(blocks[5].motion.path_caps.a));  // after the range: no cap
  }
  SECTION("LIFT-3 more than 20 internal blocks: the summit is the peak, the path slowed to reach it") {
    m.lift_method = LiftMethod::path_based;
    std::vector<Block> many = range_blocks(25);
    for (size_t k = 1; k <= 25; ++k) {  // 25 x 0.8 mm at 100 mm/s: 0.2 s, too short for 20 mm up and 18 down
      many[k].motion.start[0] = 0.8 * (k - 1);
      many[k].motion.end[0] = 0.8 * k;
    }
    std::vector<Block> few = range_blocks(20);  // 20 x 1 mm: the same 0.2 s
    for (size_t k = 1; k <= 20; ++k) {
      few[k].motion.start[0] = 1.0 * (k - 1);
      few[k].motion.end[0] = 1.0 * k;
    }
    const LiftRange overflow = prepare_lift_ranges(many, m, origin)[0];
    const LiftRange seen = prepare_lift_ranges(few, m, origin)[0];
    CHECK(overflow.internal_blocks == 25);
    CHECK(overflow.profile.summit() == Approx(30));
    CHECK(overflow.v_plan < 100);
    CHECK(seen.profile.summit() < 30);
    CHECK(seen.v_plan == Approx(100));
  }
  SECTION("LIFT-4 a path shorter than P-CHAN-00244 suppresses the lift: straight to POS") {
    m.lift_method = LiftMethod::time_based;
    m.lift_min_dist_mm = 50;
    std::vector<Block> blocks = range_blocks(3);
    const LiftRange r = prepare_lift_ranges(blocks, m, origin)[0];
    CHECK(r.suppressed);
    CHECK(r.peak == Approx(12));
  }
  SECTION("LIFT-2 a range without path motion: the lift axis positions while the path waits") {
    m.lift_method = LiftMethod::time_based;
    std::vector<Block> blocks = range_blocks(0);
    const std::vector<LiftRange> ranges = prepare_lift_ranges(blocks, m, origin);
    REQUIRE(ranges.size() == 1);
    CHECK(ranges[0].positioning);
    CHECK(blocks[0].lift_positioning);
    CHECK(blocks[0].stops_path());
  }
  SECTION("LIFT-2 a range too short for the direct move: the path is capped so that it can land in time") {
    m.lift_method = LiftMethod::time_based;
    std::vector<Block> blocks = range_blocks(1);
    blocks[1].lift_start.reset();
    blocks[0].lift_start = LiftStart{2, false, 40, 40};  // 30 mm up in 10 mm of path at 100 mm/s
    const LiftRange r = prepare_lift_ranges(blocks, m, origin)[0];
    const double direct = positioning_time(10, 40, advanced_lifting_limits(m.axes[2], m.cycle_time_s()));
    CHECK(blocks[1].motion.path_caps.v == Approx(10 / ((direct + 2 * m.cycle_time_s()) * m.override_max_percent / 100.0)));
    CHECK(r.v_ahead[1] == Approx(blocks[1].motion.path_caps.v));
  }
  SECTION("LIFT-5 #FLUSH: a block with LIFT_END and LIFT_START ends one range and begins the next") {
    m.lift_method = LiftMethod::time_based;
    std::vector<Block> blocks = range_blocks(2);
    Block flush;
    flush.lift_end = true;
    flush.lift_start = LiftStart{2, false, 12, 30};
    blocks.insert(blocks.begin() + 2, flush);
    const std::vector<LiftRange> ranges = prepare_lift_ranges(blocks, m, origin);
    REQUIRE(ranges.size() == 2);
    CHECK(ranges[0].end == 2);
    CHECK(ranges[1].start == 2);
    CHECK(ranges[1].end == 4);
  }
  SECTION("LIFT-5 program end without LIFT_END: the range ends with the last block") {
    m.lift_method = LiftMethod::time_based;
    std::vector<Block> blocks = range_blocks(2);
    blocks.resize(3);
    const std::vector<LiftRange> ranges = prepare_lift_ranges(blocks, m, origin);
    REQUIRE(ranges.size() == 1);
    CHECK(ranges[0].end == 2);
  }
}

// TF5200_lift_function.txt, "Path smoothing and lifting": smoothing is
// suppressed at the start and end of lifting where the lift axis moves in
// the block before LIFT_START or directly after LIFT_END (1st case); the
// other axes are smoothed where it does not (2nd case).
TEST_CASE("LIFT-2 LIFT-3 KRN-6 contouring into and out of an Advanced Lifting range only where the lift axis does not "
          "move beside it; none into, out of or inside a Lifting range",
          "[lift]") {
  MachineConfig m = test::xyz_machine();
  std::vector<Block> blocks;
  for (int i = 0; i < 5; ++i) {
    blocks.push_back(line({10.0 * i, 5.0 * (i % 2), 10}, {10.0 * (i + 1), 5.0 * ((i + 1) % 2), 10}, 100));
    blocks.back().transition = BlockTransition::contour;
  }
  blocks[1].lift_start = LiftStart{2, false, 10, 30};
  blocks[3].lift_end = true;
  auto transitions = [&](std::vector<Block> b, LiftMethod method, const Block* next_motion = nullptr) {
    m.lift_method = method;
    prepare_lift_ranges(b, m, {0, 0, 10}, next_motion);
    std::string out;
    for (const Block& block : b) out += block.transition == BlockTransition::contour ? 'C' : 's';
    return out;
  };
  SECTION("2nd case: the lift axis stands still before and after the range") {
    CHECK(transitions(blocks, LiftMethod::path_based) == "ssssC");  // Lifting: 1st case always, none inside
    CHECK(transitions(blocks, LiftMethod::time_based) == "CCCCC");
  }
  SECTION("1st case: the lift axis moves in the block before LIFT_START") {
    std::vector<Block> b = blocks;
    b[0].motion.start[2] = 0;
    CHECK(transitions(b, LiftMethod::path_based) == "ssssC");
    CHECK(transitions(b, LiftMethod::time_based) == "sCCCC");
  }
  SECTION("1st case: the lift axis moves in the block directly after LIFT_END") {
    std::vector<Block> b = blocks;
    b[4].motion.end[2] = 0;
    CHECK(transitions(b, LiftMethod::path_based) == "ssssC");
    CHECK(transitions(b, LiftMethod::time_based) == "CCCsC");
  }
  SECTION("1st case: a full circle in the lift axis' plane moves it, though it ends where it began") {
    // Fuzz lift seed 19001122 (docs/FUZZ.md X): a G19 circle before
    // LIFT_START was contoured into the range; Z stepped 0.07 mm in a cycle.
    std::vector<Block> b = blocks;
    Motion& circle = b[0].motion;
    circle.type = MotionType::arc_ccw;
    circle.plane = {1, 2};  // G19: Y Z
    circle.start = {0, 0, 10};
    circle.end = {10, 0, 10};  // X linear: a helix, Y and Z back where they began
    circle.center = {0, 5};
    CHECK(transitions(b, LiftMethod::time_based) == "sCCCC");
    std::vector<Block> after = blocks;
    after[4].motion = circle;
    after[4].motion.start = after[4].motion.end = {50, 5, 10};
    after[4].motion.end[0] = 60;
    CHECK(transitions(after, LiftMethod::time_based) == "CCCsC");
  }
  SECTION("the block after the range not yet among the blocks (streamed): the next motion block decides") {
    std::vector<Block> b(blocks.begin(), blocks.begin() + 4);
    Block after = blocks[4];
    CHECK(transitions(b, LiftMethod::time_based, &after) == "CCCC");
    after.motion.end[2] = 0;
    CHECK(transitions(b, LiftMethod::time_based, &after) == "CCCs");
    CHECK(transitions(b, LiftMethod::time_based, nullptr) == "CCCs");  // nothing follows
  }
  SECTION("#FLUSH: where one range ends and the next begins, the lift axis reaches its target: no contouring") {
    std::vector<Block> b = blocks;
    b[2].lift_start = LiftStart{2, false, 10, 30};  // LIFT_END and LIFT_START in N2
    CHECK(transitions(b, LiftMethod::time_based) == "CssCC");
  }
}
