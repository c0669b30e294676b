// continued_program (block_search.hpp): the approach, the collected
// commands, then the program from the continuation point on (DPS-3).
#include <cmath>
#include <cstddef>

#include "block_search.hpp"
#include "motion_parts.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {

// A leg shorter than this does not move.
constexpr double no_travel_mm = tolerance::length_mm;

bool moves(const std::vector<double>& from, const std::vector<double>& to) {
  for (size_t i = 0; i < from.size(); ++i)
    if (std::abs(to[i] - from[i]) > no_travel_mm) return true;
  return false;
}

// The motion the program goes on with there: the continuation's block's,
// or (a block without motion) the next motion's. None: a rapid.
const Motion* continued_motion(const BlockWindow& blocks, size_t k) {
  for (size_t i = k; blocks.has(i); ++i)
    if (blocks[i].has_motion) return &blocks[i].motion;
  return nullptr;
}

// Repositioning to the continuation point: the tool axis Z clear of the
// part first when it goes up, last when it goes down; the other axes
// together. G00 if the program goes on with a rapid, else G01 at its feed.
// Each leg ends at standstill.
std::vector<Block> approach(const BlockWindow& blocks, const Continuation& c, const std::vector<double>& from,
                            const MachineConfig& machine) {
  std::vector<Block> legs;
  const std::vector<double>& to = c.position;
  if (to.size() != from.size() || from.size() != machine.axes.size()) return legs;
  const int z = machine.axis_index("Z");
  std::vector<double> corner = from;  // where the first leg ends
  const bool z_up = z >= 0 && to[static_cast<size_t>(z)] > from[static_cast<size_t>(z)];
  for (size_t i = 0; i < corner.size(); ++i)
    if ((static_cast<int>(i) == z) == z_up) corner[i] = to[i];
  const Block& continuation = blocks[c.block];
  const Motion* motion = continued_motion(blocks, c.block);
  const std::vector<double>* points[] = {&from, &corner, &to};
  for (int leg = 0; leg < 2; ++leg) {
    const std::vector<double>& start = *points[leg];
    const std::vector<double>& end = *points[leg + 1];
    if (!moves(start, end)) continue;
    Block block;
    block.nc_line = continuation.nc_line;
    block.block_nr = continuation.block_nr;
    block.block_count = continuation.block_count;
    block.has_motion = true;
    block.motion.type = motion && motion->type != MotionType::rapid ? MotionType::linear : MotionType::rapid;
    block.motion.feed = motion ? motion->feed : 0.0;
    block.motion.start = start;
    block.motion.end = end;
    block.slope = continuation.slope;
    block.transition = BlockTransition::exact_stop;
    legs.push_back(block);
  }
  return legs;
}

// The rest of the continuation's block from a point inside it: its motion
// from there; its own commands ran on the way (search_block collected them).
Block rest_of_block(Block block, const std::vector<double>& point, const MachineConfig& machine) {
  const std::optional<Motion> rest = rest_of_motion(block.motion, point, false, machine);
  block.has_motion = rest.has_value();
  if (rest) block.motion = *rest;
  block.m_functions.clear();
  block.dwell_s = 0;
  block.programmed_stop.reset();
  block.insert_cmd.reset();
  block.distance_prog_start.reset();
  block.lift_start.reset();
  return block;
}

}  // namespace

std::deque<Block> continued_start(BlockWindow& blocks, const Continuation& continuation,
                                  const std::vector<double>& from, const MachineConfig& machine,
                                  size_t& continuation_index) {
  std::deque<Block> out;
  continuation_index = 0;
  if (!blocks.has(continuation.block)) return out;
  const Block& at = blocks[continuation.block];
  Block first = continuation.at_block_start ? at : rest_of_block(at, continuation.position, machine);
  // A continuation within round-off of its block's end leaves nothing of
  // the block: the approach ends where the next motion starts, on that end
  // (it ended 0.4 pm short, a jump into the next block of 40,000.43 mm/s^3
  // for 40,000: contour fuzz seed 7000444).
  Continuation approached = continuation;
  if (!continuation.at_block_start && at.has_motion && !first.has_motion) approached.position = at.motion.end;
  const std::vector<Block> legs = approach(blocks, approached, from, machine);
  out.assign(legs.begin(), legs.end());
  // The approach covers no distance (the channel presets dist_prog_start
  // to the continuation's).
  if (!out.empty()) out.front().distance_prog_start = DistanceProgStart::off;
  if (!continuation.m_functions.empty() || continuation.insert_cmd) {
    if (out.empty()) {  // a block of its own, before any motion
      Block carrier;
      carrier.nc_line = at.nc_line;
      carrier.block_nr = at.block_nr;
      carrier.block_count = at.block_count;
      out.push_back(carrier);
    }
    out.front().m_functions = continuation.m_functions;
    out.front().insert_cmd = continuation.insert_cmd;
  }
  // Counting goes on where the approach ends. The block's own command
  // applies at the same moment and is already in the continuation's
  // distance and state: ON is ON, CLEAR made it 0, OFF stopped counting.
  if (continuation.distance_counting) first.distance_prog_start = DistanceProgStart::on;
  continuation_index = out.size();
  out.push_back(first);
  blocks.forget_before(continuation.block + 1);
  for (Block& block : blocks.take_all()) out.push_back(std::move(block));
  return out;
}

std::vector<Block> continued_program(const std::vector<Block>& blocks, const Continuation& continuation,
                                     const std::vector<double>& from, const MachineConfig& machine) {
  BlockWindow window(blocks);
  size_t index = 0;
  const std::deque<Block> start = continued_start(window, continuation, from, machine, index);
  std::vector<Block> out(start.begin(), start.end());
  for (size_t i = window.first_kept(); window.has(i); ++i) out.push_back(window[i]);
  return out;
}

}  // namespace hil::cnc
