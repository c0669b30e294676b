#pragma once
// `cnc --rerun LOG` (RIG-7): feeds the PLC's answers and the drives'
// monitoring bits recorded in LOG into this build's channel in lock-step,
// and compares what it publishes with what the recorded CNC published,
// message by message.
#include <ostream>
#include <string>

namespace hil::cnc_node {

// Prints "identical ..." or the first cycle and message that differ.
// Returns 0 if identical, 1 if not; throws std::runtime_error for a log it
// cannot rerun (not an LCM log, a damaged one, no scenario, a real-time run).
int rerun(const std::string& log_path, std::ostream& out);

}  // namespace hil::cnc_node
