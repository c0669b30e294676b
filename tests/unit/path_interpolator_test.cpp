// The interpolator's interface for the channel's functions (KRN-3): a stop
// at a path position (insert stop marks, KRN-4), held within the limits.
#include <catch2/catch.hpp>

#include <cmath>
#include <deque>
#include <iterator>
#include <string>

#include "decoder.hpp"
#include "limit_check.hpp"
#include "path_interpolator.hpp"
#include "test_machine.hpp"

using namespace hil;
using namespace hil::cnc;

namespace {

struct NoObserver : PathObserver {
  void reach_block(const Block&, size_t, bool) override {}
  void travelled(double) override {}
  void finish_block(size_t) override {}
};

struct Run {
  MachineConfig machine = test::xyz_machine();
  NoObserver observer;
  PathInterpolator path{machine, observer};
  logger::LimitChecker checker{machine};
  int64_t k = 0;

  explicit Run(const std::string& program)
      : Run(decode_program(program, test::xyz_machine(), std::vector<double>(3, 0.0)).blocks) {}
  explicit Run(std::vector<Block> blocks) {
    path.load(std::move(blocks));
    path.set_velocity_factor(1.0);
    path.go_on_from_standstill(0);
  }
  double t() const { return static_cast<double>(k) * machine.cycle_time_s(); }
  PathProgress step() {
    const PathProgress progress = path.interpolate(t());
    for (size_t i = 0; i < path.setpoints().size(); ++i)
      checker.add_setpoint(static_cast<int>(i), k, path.setpoints()[i].position);
    ++k;
    return progress;
  }
};

}  // namespace

TEST_CASE("KRN-3 interpolator: a stop at a path position holds there, within the limits, until released",
          "[interpolator]") {
  Run run("N10 G01 X40 F6000\nN20 X80 Y10\nN30 X120\nM30\n");
  while (run.t() < 0.2) run.step();
  const double x_then = run.path.setpoints()[0].position;
  REQUIRE(run.path.path_velocity() > 50);
  run.path.stop_after(run.t() - run.machine.cycle_time_s(), 50.0);  // from x_then: across N10's end, into N20
  int64_t held = 0;
  for (int i = 0; i < 20000 && held < 200; ++i) {
    run.step();
    if (run.path.at_stop(run.t())) ++held;
  }
  REQUIRE(held == 200);
  CHECK(run.path.path_velocity() == 0);
  // 50 mm of path from x_then: the rest of N10 along X, then along N20.
  const double rest_of_n10 = 40 - x_then, along_n20 = 50 - rest_of_n10;
  const double n20_length = std::hypot(40.0, 10.0);
  CHECK(run.path.setpoints()[0].position == Approx(40 + 40 * along_n20 / n20_length).margin(1e-6));
  CHECK(run.path.setpoints()[1].position == Approx(10 * along_n20 / n20_length).margin(1e-6));
  run.path.release_stop();
  PathProgress progress = PathProgress::moving;
  for (int i = 0; i < 20000 && progress != PathProgress::all_blocks_run; ++i) progress = run.step();
  CHECK(progress == PathProgress::all_blocks_run);
  CHECK(run.path.setpoints()[0].position == Approx(120));
  CHECK(run.checker.finish().violations.empty());
}

TEST_CASE("KRN-3 interpolator: a stop closer than the braking distance moves out to where the path can stop",
          "[interpolator]") {
  Run run("N10 G01 X200 F6000\nM30\n");
  while (run.t() < 0.5) run.step();
  REQUIRE(run.path.path_velocity() == Approx(100));
  run.path.stop_after(run.t(), 0.01);
  int i = 0;
  while (!run.path.at_stop(run.t()) && i++ < 5000) run.step();
  REQUIRE(run.path.at_stop(run.t()));
  run.step();
  CHECK(run.path.path_velocity() == 0);
  CHECK(run.path.setpoints()[0].position < 200);
  CHECK(run.checker.finish().violations.empty());
}

TEST_CASE("KRN-3 interpolator: a block whose geometry is not finite is never moved; the path stops before it",
          "[interpolator]") {
  // A block no decoder should let through: an arc of radius 1e308 (the
  // decoder refuses it; this is the interpolator's own last line of defence).
  Block arc;
  arc.has_motion = true;
  arc.nc_line = 2;
  arc.motion.type = MotionType::arc_cw;
  arc.motion.start = {10, 0, 0};
  arc.motion.end = {10, 200, 0};
  arc.motion.center[0] = 10;
  arc.motion.center[1] = 1e308;
  arc.motion.feed = 100;
  std::vector<Block> blocks = decode_program("N10 G01 X10 F6000\n", test::xyz_machine(), {0, 0, 0}).blocks;
  blocks.push_back(arc);
  Run run(blocks);
  PathProgress progress = PathProgress::moving;
  for (int i = 0; i < 20000 && progress == PathProgress::moving; ++i) {
    progress = run.step();
    for (const AxisSetpoint& s : run.path.setpoints()) {
      REQUIRE(std::isfinite(s.position));
      REQUIRE(std::isfinite(s.velocity));
      REQUIRE(std::isfinite(s.acceleration));
    }
  }
  CHECK(progress == PathProgress::invalid_block);
  CHECK(run.path.invalid_block() == size_t{1});
  CHECK(run.path.setpoints()[0].position == 10);
  CHECK(run.path.setpoints()[1].position == 0);
  CHECK(run.path.path_velocity() == 0);
  CHECK(run.checker.finish().violations.empty());
}

namespace {

// Counts the blocks the interpolator reads (issue 17: a program is
// streamed as the look-ahead needs it).
struct CountingSource : QueuedBlocks {
  using QueuedBlocks::QueuedBlocks;
  size_t read = 0;
  bool next(Block& block) override {
    const bool got = QueuedBlocks::next(block);
    if (got) ++read;
    return got;
  }
};

struct FinishCounter : NoObserver {
  size_t finished = 0;
  void finish_block(size_t) override { ++finished; }
};

}  // namespace

TEST_CASE("KRN-3 interpolator: the look-ahead fills its 120 blocks over cycles, so many a cycle besides those the "
          "path finishes, and the path starts in the first cycle (issue 36)",
          "[interpolator]") {
  std::string program = "N10 G01 F6000\n";
  for (int i = 1; i <= 400; ++i) program += "X" + std::to_string(0.1 * i) + (i % 2 ? " Y0.001\n" : " Y0\n");
  program += "M30\n";
  const MachineConfig machine = test::xyz_machine();
  std::vector<Block> decoded = decode_program(program, machine, {0, 0, 0}).blocks;
  CountingSource source(std::deque<Block>(std::make_move_iterator(decoded.begin()), std::make_move_iterator(decoded.end())));
  FinishCounter observer;
  PathInterpolator path(machine, observer);
  logger::LimitChecker checker(machine);
  path.load(source, 0);
  path.set_velocity_factor(1.0);
  path.go_on_from_standstill(0);
  const size_t per_cycle = PathInterpolator::look_ahead_fill_per_cycle;
  // N10 without motion and one block read ahead besides the motion blocks.
  CHECK(source.read <= per_cycle + 2);
  PathProgress progress = PathProgress::moving;
  int64_t k = 0, first_moving = -1;
  size_t full_at = 0;
  for (; k < 20000 && progress == PathProgress::moving; ++k) {
    const size_t read_before = source.read, finished_before = observer.finished;
    progress = path.interpolate(static_cast<double>(k) * machine.cycle_time_s());
    CHECK(source.read - read_before <= per_cycle + (observer.finished - finished_before));
    if (first_moving < 0 && path.path_velocity() > 0) first_moving = k;
    if (full_at == 0 && source.read >= LookAhead::fct_look_ahead_standard + observer.finished) full_at = static_cast<size_t>(k);
    for (size_t i = 0; i < path.setpoints().size(); ++i) checker.add_setpoint(static_cast<int>(i), k, path.setpoints()[i].position);
  }
  CHECK(progress == PathProgress::all_blocks_run);
  CHECK(first_moving == 1);  // t = 0 is the start itself
  CHECK(full_at > 0);
  CHECK(full_at <= LookAhead::fct_look_ahead_standard / per_cycle + 1);
  CHECK(path.setpoints()[0].position == Approx(40));
  CHECK(checker.finish().violations.empty());
}
