#include "program_check.hpp"

#include <iostream>
#include <sstream>

#include "config_error.hpp"
#include "line_source.hpp"
#include "program_decoder.hpp"
#include "run_scenario.hpp"
#include "scenario_set.hpp"

namespace hil::rig {

void check_nc_program(const Scenario& scenario) {
  if (!scenario.expected_events.empty() || scenario.allow_errors) return;
  // Streamed, the blocks dropped as they come: a program of any length in
  // the same memory (docs/ARCHITECTURE.md, "Programs of any length").
  const cnc::ProgramText text = cnc::program_text(scenario.nc_program);
  cnc::ProgramDecoder decoder(text(), scenario.machine, std::vector<double>(scenario.machine.axes.size(), 0.0));
  cnc::Block block;
  while (decoder.next(block)) {
  }
  if (!decoder.error()) return;
  const Event& error = *decoder.error();
  std::ostringstream where;
  where << nc_line_place(scenario, error.nc_line);
  // The refused word's column, else where the refused block begins.
  std::istringstream lines(scenario.nc_program);
  std::string line;
  for (int64_t k = 0; k < error.nc_line && std::getline(lines, line); ++k) {
  }
  const size_t first = line.find_first_not_of(" \t");
  const int64_t column = error.column > 0 ? error.column : first == std::string::npos ? 1 : static_cast<int64_t>(first) + 1;
  if (error.nc_line > 0) where << " column " << column;
  if (error.block_nr > 0) where << " (N" << error.block_nr << ")";
  if (error.id > 0) where << ", error " << error.id;
  throw ConfigError(where.str() + ": " + error.message);
}

int validate_scenario_files(const std::vector<std::string>& files) {
  int status = 0;
  for (const std::string& file : files) {
    RunOptions options;
    options.scenario_file = file;
    try {
      load_valid_scenario_set(options);
      std::cout << file << ": ok\n";
    } catch (const ConfigError& e) {
      std::cout << e.what() << '\n';
      status = 2;
    }
  }
  return status;
}

}  // namespace hil::rig
