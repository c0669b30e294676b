#include "collected_commands.hpp"

#include <algorithm>

namespace hil::cnc {
namespace {

// The index of nr's group, -1 if it has none.
int group_of(int nr) {
  for (size_t g = 0; g < m_function_groups.size(); ++g)
    if (std::find(m_function_groups[g].begin(), m_function_groups[g].end(), nr) != m_function_groups[g].end())
      return static_cast<int>(g);
  return -1;
}

}  // namespace

void CollectedCommands::pass(const Block& block) {
  for (const MFunction& m : block.m_functions) {
    const int group = m.address == 'M' ? group_of(m.nr) : -1;
    // What this one replaces: its group's earlier one, or its own earlier
    // occurrence; of S, T and D (KRN-8) the last one counts.
    const auto replaced = [&](const MFunction& earlier) {
      if (earlier.address != m.address) return false;
      if (m.address == 'S' || m.address == 'T' || m.address == 'D') return true;
      return group >= 0 ? group_of(earlier.nr) == group : earlier.nr == m.nr;
    };
    m_functions_.erase(std::remove_if(m_functions_.begin(), m_functions_.end(), replaced), m_functions_.end());
    m_functions_.push_back({m.nr, 0.0, m.address, m.value});
  }
  if (block.insert_cmd) insert_cmd_ = block.insert_cmd;
}

}  // namespace hil::cnc
