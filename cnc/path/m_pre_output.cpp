#include "m_pre_output.hpp"

#include <algorithm>
#include <cstddef>

#include "motion_parts.hpp"
#include "path_segment.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {

constexpr int pre_output_lookahead_blocks = 10;  // P-CHAN-00603 default
using tolerance::shortest_part_mm;

// Puts `m` `distance` mm before the end of `out`'s path: between two parts
// of the motion block there, or before the earliest block searched.
// False if the path before it was shorter than the pre-output path.
bool insert_pre_output(RingQueue<Block>& out, const MFunction& m, const Block& owner, const MachineConfig& machine) {
  double distance = m.pre_output_mm;
  bool reached = false;
  size_t insert_at = out.size();
  int searched = 0;
  for (size_t i = out.size(); i-- > 0 && searched < pre_output_lookahead_blocks;) {
    if (!out[i].has_motion) continue;
    ++searched;
    insert_at = i;
    const PathSegment segment(out[i].motion, machine);
    if (distance >= segment.length() - shortest_part_mm) {  // lies before this block
      distance -= segment.length();
      reached = distance <= shortest_part_mm;
      if (reached) break;
      continue;
    }
    reached = true;
    if (distance <= shortest_part_mm) {  // at its end
      insert_at = i + 1;
      break;
    }
    Block second = out[i];
    const std::vector<double> split = segment.position(segment.length() - distance);
    out[i].motion = motion_until(out[i].motion, split);
    out[i].program_end = false;  // M30 ends the second part
    out[i].lift_end = false;     // a lift range begins with the first part, ends with the second (LIFT-1)
    second.motion = motion_from(second.motion, split);
    second.continues_block = true;
    second.m_functions.clear();  // the line's own M functions went out before its first part
    second.dwell_s = 0;
    second.lift_start.reset();
    out.insert(out.begin() + static_cast<std::ptrdiff_t>(i) + 1, std::move(second));
    insert_at = i + 1;
    break;
  }
  // The M function stands as a block without motion of the line it goes out in.
  const Block& at = insert_at < out.size() ? out[insert_at] : owner;
  Block carrier;
  carrier.nc_line = at.nc_line;
  carrier.block_count = at.block_count;
  carrier.block_nr = at.block_nr;
  carrier.m_functions.push_back({m.nr, 0, m.address, m.value});
  out.insert(out.begin() + static_cast<std::ptrdiff_t>(insert_at), std::move(carrier));
  return reached;
}

}  // namespace

void MPreOutput::add(Block&& block) {
  std::vector<MFunction> stay;
  for (const MFunction& m : block.m_functions) {
    if (m.pre_output_mm <= 0) {
      stay.push_back(m);
      continue;
    }
    const bool reached = insert_pre_output(held_, m, block, machine_);
    motion_held_ = static_cast<size_t>(
        std::count_if(held_.begin(), held_.end(), [](const Block& b) { return b.has_motion; }));
    if (reached) continue;
    Event short_path;
    short_path.severity = Severity::warning;
    short_path.parameter = "P-CHAN-00070";
    short_path.nc_line = block.nc_line;
    short_path.block_nr = block.block_nr;
    short_path.value = m.pre_output_mm;
    short_path.message = "M" + std::to_string(m.nr) + ": pre-output path " + std::to_string(m.pre_output_mm) +
                         " mm reaches past the program start or the " + std::to_string(pre_output_lookahead_blocks) +
                         " motion blocks searched (P-CHAN-00603); output as early as they allow";
    warnings_.push_back(short_path);
  }
  if (stay.size() != block.m_functions.size()) block.m_functions = std::move(stay);
  if (!(block.has_motion || block.has_command())) return;
  if (block.has_motion) ++motion_held_;
  held_.push_back(std::move(block));
}

// A pre-output goes in at or after the earliest of the last 10 motion
// blocks (insert_pre_output): what lies before it is final.
void MPreOutput::release_final() {
  final_ = 0;
  size_t motion = motion_held_;
  while (final_ < held_.size() && (motion > static_cast<size_t>(pre_output_lookahead_blocks) ||
                                   !held_[final_].has_motion)) {
    if (held_[final_].has_motion) --motion;
    ++final_;
  }
}

// Read in place at held_'s back (a Block is large to move); one with an M
// function to pre-output goes through add, which looks at the blocks before it.
bool MPreOutput::take_next() {
  Block& in = held_.emplace_back();
  bool read = false;
  try {
    read = upstream_.next(in);
  } catch (...) {
    held_.pop_back();
    throw;
  }
  if (!read) {
    held_.pop_back();
    return false;
  }
  if (std::any_of(in.m_functions.begin(), in.m_functions.end(), [](const MFunction& m) { return m.pre_output_mm > 0; })) {
    Block block = std::move(in);
    held_.pop_back();
    add(std::move(block));
    return true;
  }
  if (!(in.has_motion || in.has_command())) {
    held_.pop_back();
    return true;
  }
  if (in.has_motion) ++motion_held_;
  return true;
}

bool MPreOutput::next(Block& block) {
  while (final_ == 0) {
    if (ended_ || !take_next()) {
      ended_ = true;
      if (held_.empty()) return false;
      final_ = held_.size();
      break;
    }
    release_final();
  }
  block = std::move(held_.front());
  held_.pop_front();
  if (block.has_motion) --motion_held_;
  --final_;
  return true;
}

std::vector<Block> apply_m_pre_output(std::vector<Block> blocks, const MachineConfig& machine,
                                      std::vector<Event>& warnings) {
  QueuedBlocks all(std::deque<Block>(std::make_move_iterator(blocks.begin()), std::make_move_iterator(blocks.end())));
  MPreOutput stage(all, machine);
  std::vector<Block> out;
  Block block;
  while (stage.next(block)) out.push_back(std::move(block));
  for (Event& warning : stage.take_warnings()) warnings.push_back(std::move(warning));
  return out;
}

}  // namespace hil::cnc
