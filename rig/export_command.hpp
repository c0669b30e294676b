#pragma once
// `hil export RUN.lcmlog --csv DIR` (RIG-4): a run's log as CSV files, one
// per channel (logger/csv_export.hpp), for tools outside the rig.
#include <string>

namespace hil::rig {

// Writes the files and says on stdout what went where, and what was left
// out (channels of unknown types, undecodable messages). Returns 0; throws
// std::runtime_error for a file that is not an LCM log (exit status 2).
int export_csv_command(const std::string& log, const std::string& dir);

}  // namespace hil::rig
