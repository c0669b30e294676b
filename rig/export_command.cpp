#include "export_command.hpp"

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "csv_export.hpp"

namespace hil::rig {

int export_csv_command(const std::string& log, const std::string& dir) {
  const logger::CsvExport result = logger::export_csv(log, dir);
  std::cout << "exported " << log << ": " << result.messages << " messages, " << result.channels.size()
            << " channel(s) into " << dir << '\n'
            << "time: " << (result.cycle_s ? "t_s = cycle * " + std::to_string(*result.cycle_s) +
                                                 " s (simulated) where the message has a cycle; log_t_s = the log's "
                                                 "timestamp since its first message"
                                           : std::string("log_t_s only (no HIL_MANIFEST with the cycle time)"))
            << '\n';
  size_t width = 0;
  for (const auto& c : result.channels) width = std::max(width, std::filesystem::path(c.file).filename().string().size());
  int64_t skipped = 0;
  for (const auto& c : result.channels) {
    std::cout << "  " << std::left << std::setw(static_cast<int>(width)) << std::filesystem::path(c.file).filename().string()
              << "  " << std::setw(16) << c.type << std::right << std::setw(9) << c.rows << " rows"
              << (c.skipped ? ", " + std::to_string(c.skipped) + " undecodable message(s) left out" : "")
              << (c.too_wide ? ", " + std::to_string(c.too_wide) + " message(s) of more columns than any rig message left out"
                             : "")
              << '\n';
    skipped += c.skipped;
  }
  for (const auto& [channel, messages] : result.unknown)
    std::cout << "not exported: " << channel << " (" << messages << " message(s) of a type this build does not know)\n";
  for (const auto& [channel, messages] : result.too_many)
    std::cout << "not exported: " << channel << " (" << messages << " message(s); more channels than one export writes)\n";
  std::cout << "left out: " << result.unknown.size() << " channel(s) of unknown type, " << skipped
            << " undecodable message(s)\n";
  if (!result.too_many.empty())
    std::cout << "left out: " << result.too_many.size() << " channel(s) beyond the " << result.channels.size()
              << " one export writes\n";
  // The rows above are what the file's whole records hold; a damaged file may have lost others.
  if (!result.damage.empty()) std::cout << "damaged: " << result.damage << '\n';
  return 0;
}

}  // namespace hil::rig
