#pragma once
// Block search (DPS-3, TF5200_distance_from_program_start.txt): where a
// program continues after an interruption, found without motion over the
// decoded program. Phase 1 runs up to the first block with the searched
// block number; type 4's phase 2 goes on by the distance from program start
// (DPS-1, with #DISTANCE PROG START ON / OFF / CLEAR as a run counts it)
// into that block or blocks after it. Knows no channel: the channel hands
// it the blocks a program start would run, and runs what it returns.
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "block.hpp"
#include "block_window.hpp"
#include "event.hpp"
#include "machine_config.hpp"

namespace hil::cnc {

// What the PLC asks for (the HLI's block_search unit, command_w).
struct BlockSearchRequest {
  int type = 4;            // 1: at the start of the block; 4: block number and covered distance
  int64_t block_nr = 0;    // N number: its first block in program order
  double distance_mm = 0;  // type 4: dist_prog_start at the continuation point
};

// Where and how the program continues.
struct Continuation {
  size_t block = 0;  // index into the searched blocks: the block the continuation point lies in
  int64_t nc_line = 0, block_nr = 0;  // of that block
  // On the block's motion (its start if it lies at the start); mm, machine axes.
  std::vector<double> position;
  bool at_block_start = true;   // the block runs whole, its own commands included
  double distance_mm = 0;       // dist_prog_start at the continuation point
  bool distance_counting = true;  // #DISTANCE PROG START ON in force there
  // The M functions a run would have output on the way, as the PLC is to
  // see them before motion resumes: the last of each M function group, an
  // M function of no group once (its last occurrence), in program order.
  std::vector<MFunction> m_functions;
  // The last #INSERT CMD on the way (ISC-8), set again at the continuation.
  std::optional<InsertCmdLine> insert_cmd;
  // A distance before the searched block's start: the continuation is moved
  // to the block's start (the text: "prevented and a warning is output").
  std::optional<Event> warning;
};

struct BlockSearchOutcome {
  std::optional<Continuation> continuation;  // none: `error`
  // No such block number; a distance beyond the program's end; G74, G100 or
  // #FLUSH WAIT between the block and the continuation (phase 2); a
  // continuation inside a lift range. With the NC line and N where one is.
  std::optional<Event> error;
};

// Over a streamed program (issue 17): reads `blocks` from its first block
// up to the continuation and the next motion block after it; the blocks
// before the searched block are forgotten as they pass, those from it to
// the continuation are kept (phase 2's distance bounds them).
BlockSearchOutcome search_block(BlockWindow& blocks, const BlockSearchRequest& request, const MachineConfig& machine);
// The same over a whole program (tests).
BlockSearchOutcome search_block(const std::vector<Block>& blocks, const BlockSearchRequest& request,
                                const MachineConfig& machine);

// The program to run from where the axes stand (`from`) on: the approach to
// the continuation point (repositioning, see docs/BLOCK_SEARCH.md), the
// collected M functions before it, then the rest of the continuation's
// block and every block after it. The approach covers no distance: the
// distance from program start goes on from the continuation's.
std::vector<Block> continued_program(const std::vector<Block>& blocks, const Continuation& continuation,
                                     const std::vector<double>& from, const MachineConfig& machine);
// The same on the window search_block(BlockWindow&) left: the continued
// program's first blocks, up to those read; taken out of `blocks`, which
// reads on after them. `continuation_index`: where the continuation's
// block (or its rest) lies in them.
std::deque<Block> continued_start(BlockWindow& blocks, const Continuation& continuation,
                                  const std::vector<double>& from, const MachineConfig& machine,
                                  size_t& continuation_index);

}  // namespace hil::cnc
