#pragma once
// Where a delete distance to go short-cuts to (DDTG-1, DDTG-5, DDTG-6, DDTG-8).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "block.hpp"
#include "block_window.hpp"

namespace hil::cnc {

struct ShortCutTarget {
  // The motion block whose end point the short cut goes to. None: no motion
  // block, or no valid marker, left before the program end (DDTG-6: 50810),
  // or `not_skippable` is set.
  std::optional<size_t> target;
  // DDTG-8: a command between the interrupted block and the target that
  // must not be skipped (error 51016); there is no short cut.
  std::optional<size_t> not_skippable;
  // DDTG-8: a command needing channel initialisation ended the search (warning
  // 51036); the short cut goes to the last motion block before it.
  std::optional<size_t> channel_initialisation;
  // No target within short_cut_search_blocks: treated as none (DDTG-6).
  bool search_limit = false;
};

// The program is streamed (issue 17): the search reads ahead at most this
// many blocks after the interrupted one, and holds them until they have run.
constexpr size_t short_cut_search_blocks = 100000;

// From a stop in block `interrupted`: the next programmed motion block
// (activation 0; the rest of the interrupted one is dropped),
// or the last motion block before the first #DEL DIST2GO marker with
// END & activation != 0 (which may be `interrupted` itself).
ShortCutTarget short_cut_target(const BlockWindow& blocks, size_t interrupted, uint32_t activation);
// The same over a whole program (tests).
ShortCutTarget short_cut_target(const std::vector<Block>& blocks, size_t interrupted, uint32_t activation);

}  // namespace hil::cnc
