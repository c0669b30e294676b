#pragma once
// What block search collects on the way to the continuation point (DPS-3):
// the M functions a run would have output, reduced to what the PLC is to
// see before motion resumes, and the last #INSERT CMD.
#include <array>
#include <optional>
#include <vector>

#include "block.hpp"

namespace hil::cnc {

// M function groups: a function replaces its group's earlier one. The rig's
// PLC knows the spindle (M03 M04 M05) and the coolant (M07 M08 M09); other
// numbers stand alone.
constexpr std::array<std::array<int, 3>, 2> m_function_groups = {{{3, 4, 5}, {7, 8, 9}}};

class CollectedCommands {
 public:
  // A block passed on the way: its M functions and #INSERT CMD.
  void pass(const Block& block);
  // The last of each group and each ungrouped number once, at its last
  // occurrence, in program order; output at once (no pre-output path:
  // there is no path before them).
  const std::vector<MFunction>& m_functions() const { return m_functions_; }
  const std::optional<InsertCmdLine>& insert_cmd() const { return insert_cmd_; }

 private:
  std::vector<MFunction> m_functions_;
  std::optional<InsertCmdLine> insert_cmd_;
};

}  // namespace hil::cnc
