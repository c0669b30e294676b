#include "block_search.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "block_places.hpp"
#include "collected_commands.hpp"
#include "path_segment.hpp"
#include "tolerances.hpp"

namespace hil::cnc {
namespace {

// A distance read where a block begins may lie a round-off below the
// search's own sum there (the run adds the same lengths in another order):
// that is the block's start, no position already skipped.
constexpr double round_off_mm = tolerance::length_mm;

std::string mm_text(double value) {
  std::ostringstream text;
  text.precision(10);
  text << value << " mm";
  return text.str();
}

std::string n_of(int64_t block_nr) { return "N" + std::to_string(block_nr); }

// "line 7 (N40)", "line 7" without an N number.
std::string line_of(const Block& block) {
  return "line " + std::to_string(block.nc_line) + (block.block_nr ? " (" + n_of(block.block_nr) + ")" : "");
}

Event search_event(Severity severity, const Block* block, const std::string& message) {
  Event event;
  event.severity = severity;
  if (block) {
    event.nc_line = block->nc_line;
    event.block_nr = block->block_nr;
  }
  event.message = message;
  return event;
}

BlockSearchOutcome refused(const Block* block, const std::string& message) {
  return {std::nullopt, search_event(Severity::error, block, "block search: " + message)};
}

// dist_prog_start as a run counts it (DPS-1, DPS-2): the command of a block
// applies when the block is reached, before its motion.
struct DistanceCount {
  double mm = 0;
  bool counting = true;  // #DISTANCE PROG START ON, the default at program start

  void reach(const Block& block) {
    if (!block.distance_prog_start) return;
    switch (*block.distance_prog_start) {
      case DistanceProgStart::on:
        counting = true;
        break;
      case DistanceProgStart::off:
        counting = false;
        break;
      case DistanceProgStart::clear:
        mm = 0;
        break;
    }
  }
};

// Phase 2 (the search by distance) passes blocks whose commands wait for an
// external signal, which it cannot simulate. #FLUSH WAIT acts where its
// block is reached: on the searched block it is still phase 1 (up to the
// block limit). G74 / G100 end their motion by the signal: on the searched
// block that motion is phase 2 once the continuation lies inside or after it.
const Block* not_simulated(const BlockWindow& blocks, size_t searched, const Continuation& c) {
  for (size_t k = searched; k <= c.block && blocks.has(k); ++k) {
    const Block& block = blocks[k];
    if (block.not_searchable.empty()) continue;
    const bool passed = k < c.block || !c.at_block_start;  // the continuation lies beyond the block's start
    const bool acts_at_start = block.not_searchable == "#FLUSH WAIT";
    if (passed && !(acts_at_start && k == searched)) return &block;
  }
  return nullptr;
}

}  // namespace

BlockSearchOutcome search_block(BlockWindow& blocks, const BlockSearchRequest& request,
                                const MachineConfig& machine) {
  if (request.type != 1 && request.type != 4)
    return refused(nullptr, "type " + std::to_string(request.type) +
                                " is not supported (1: at a block's start, 4: block number and covered distance)");
  const bool by_distance = request.type == 4;
  const double distance = request.distance_mm;
  if (by_distance && !(std::isfinite(distance) && distance >= 0))
    return refused(nullptr, "distance " + mm_text(distance) + " is no distance from program start (>= 0 mm)");
  // Phase 1: up to the block limit, the searched block's start; the blocks
  // passed are not kept (the program is streamed, issue 17).
  DistanceCount count;
  CollectedCommands collected;
  PassedBlocks passed;
  size_t searched = blocks.first_kept();
  for (;; ++searched) {
    if (!blocks.has(searched)) return refused(nullptr, "no block " + n_of(request.block_nr) + " in the program");
    const Block& block = blocks[searched];
    if (request.block_nr > 0 && block.block_nr == request.block_nr) break;
    count.reach(block);
    if (block.has_motion && count.counting) count.mm += PathSegment(block.motion, machine).covered_distance();
    collected.pass(block);
    passed.pass(block);
    blocks.forget_before(searched);
  }
  blocks.forget_before(searched);
  count.reach(blocks[searched]);
  Continuation c;
  c.block = searched;
  c.distance_mm = count.mm;
  c.distance_counting = count.counting;
  const Block& limit = blocks[searched];

  if (by_distance && distance < count.mm - round_off_mm) {
    // The text: moving the continuation back to a position already skipped is prevented, with a warning.
    c.warning = search_event(Severity::warning, &limit,
                             "block search: distance " + mm_text(distance) + " lies before block " +
                                 n_of(request.block_nr) + " (" + mm_text(count.mm) +
                                 " at its start): the continuation cannot be moved back to a position already "
                                 "skipped (DPS-3); it continues at the start of " +
                                 n_of(request.block_nr));
  } else if (by_distance && distance > count.mm) {
    // Phase 2: on by the distance, from the searched block's motion on.
    bool found = false;
    for (size_t k = searched; blocks.has(k) && !found; ++k) {
      const Block& block = blocks[k];
      if (k > searched) count.reach(block);
      if (block.has_motion && count.counting) {
        const PathSegment segment(block.motion, machine);
        const double covered = segment.covered_distance();
        if (count.mm < distance && distance <= count.mm + covered) {
          // Along one block the covered distance grows with the path length
          // (a line's axes, an arc's angle and its linear axes all move in
          // proportion to it), so the fraction of one is that of the other.
          const double fraction = (distance - count.mm) / covered;
          c.block = k;
          c.at_block_start = false;
          c.position = segment.position(fraction * segment.length());
          c.distance_mm = distance;
          c.distance_counting = true;
          found = true;
        }
        count.mm += covered;
      }
      collected.pass(block);  // passed on the way, or the continuation lies inside it
      if (!found && block.program_end) break;
    }
    if (!found)
      return refused(&limit, "distance " + mm_text(distance) +
                                 " lies beyond the program's end (the program counts up to " + mm_text(count.mm) + ")");
  }
  // Phase 2's blocks up to the continuation are kept: bounded by the distance searched.
  for (size_t k = searched; k < c.block; ++k) passed.pass(blocks[k]);
  if (c.at_block_start) c.position = passed.position_at_start(blocks, c.block);
  c.m_functions = collected.m_functions();
  c.insert_cmd = collected.insert_cmd();

  if (const Block* block = not_simulated(blocks, searched, c))
    return {std::nullopt,
            search_event(Severity::error, block,
                         block->not_searchable + " in " + line_of(*block) + " lies between block " +
                             n_of(request.block_nr) +
                             " and the continuation point: G74, G100 and #FLUSH WAIT cannot be simulated in a "
                             "search by distance (DPS-3)")};
  if (passed.in_lift_range(blocks, c.block, c.at_block_start))
    return {std::nullopt, search_event(Severity::error, &blocks[c.block],
                                       "block search into a lift range is not supported (LIFT-1)")};
  c.nc_line = blocks[c.block].nc_line;
  c.block_nr = blocks[c.block].block_nr;
  return {c, std::nullopt};
}

BlockSearchOutcome search_block(const std::vector<Block>& blocks, const BlockSearchRequest& request,
                                const MachineConfig& machine) {
  BlockWindow window(blocks);
  return search_block(window, request, machine);
}

}  // namespace hil::cnc
