#pragma once
// Which scenarios of a suite run this time (issue 37, RIG-5): `-k PATTERN`
// (as pytest's, a part of the file's path or the scenario's name), `--lf`
// (those that failed when this folder last ran them), `--list` (show what
// would run). The record `--lf` reads is .hil/last-failed in the current
// folder, updated by every suite run.
#include <string>
#include <vector>

#include "suite_run.hpp"

namespace hil::rig {

// The record of failed scenario files below the current folder.
constexpr const char* last_failed_file = ".hil/last-failed";

// The files whose path or scenario name contains one of `patterns` (case
// ignored; "not PATTERN" leaves out what it matches); all if none given.
std::vector<std::string> matching(const std::vector<std::string>& files, const std::vector<std::string>& patterns);

// The files the record names; `note` says what happened when it names none
// of them (then all run, as pytest's --lf does).
std::vector<std::string> last_failed(const std::vector<std::string>& files, std::string& note);

// The record after `suite`: its failed and erroneous files added, its passed
// ones taken out, the files it did not run kept.
void record_failures(const SuiteResult& suite);

// "file  name  [requirements]" per file, and how many.
std::string list_scenarios(const std::vector<std::string>& files);

}  // namespace hil::rig
