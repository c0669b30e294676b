#pragma once
// What every executable of the rig does with its command line (issue 19):
// `--version` prints the project version and the git commit it was built
// from; a command-line error prints CLI11's message and exits 2, as the
// README promises (CLI11's own codes are 105, 106, ...).
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace hil {

// "0.1.0 (git 1a2b3c4d5e6f)"
std::string build_version();

// Adds --version to `app` and parses; returns the exit status if the program should end now (0 after
// --help or --version, 2 after an error), nothing if it should go on.
std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv);

}  // namespace hil

// In main(): CLI::App app{...}; ... HIL_PARSE_COMMAND_LINE(app, argc, argv);
#define HIL_PARSE_COMMAND_LINE(app, argc, argv)                                   \
  if (const std::optional<int> hil_exit = ::hil::parse_command_line(app, argc, argv)) \
  return *hil_exit
