#pragma once
// `hil run --in-process` (issue 17): every node of the rig — the CNC, one
// drive per axis, the PLC, the logger — in this process and this thread,
// on the in-process bus. The same node code as the processes run, the same
// messages in the same log, checked and judged the same way; what is left
// out is the network and the processes, so it is for the many scenarios
// where those are not what a test is about.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "verdict.hpp"

namespace hil::rig {

// Runs the scenario `resolved_file` (as hil run writes it: every node
// reads it, as the processes do), writes the log to `log_file` and what the
// nodes say to `output_file`; returns each node's exit status as its
// process would (cnc, logger, every axis_sim, plc_sim). `pace`: as CncTiming's.
std::vector<logger::ProcessExit> run_in_process(const std::string& resolved_file, const std::string& log_file,
                                                const std::string& output_file, int64_t run_id, double pace = 0);

}  // namespace hil::rig
