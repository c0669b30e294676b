#pragma once
// `hil golden LOG --out FILE` and `hil compare A B` (issue 35, RIG-7,
// docs/GOLDEN.md): a run's golden trace written; two logs compared byte by
// byte, or - where either is a golden trace - both as traces within
// logger::golden_tolerance, naming channel, cycle, field and both values.
#include <iosfwd>
#include <string>

namespace hil::rig {

// 0 written, 2 the log cannot be read (said on stderr by the caller's catch).
// `comment`: where it came from (default: the log's path).
int write_golden_trace(const std::string& log, const std::string& out, const std::string& comment, std::ostream& said);
// 0 same, 1 different.
int compare_command(const std::string& a, const std::string& b, std::ostream& said);

}  // namespace hil::rig
