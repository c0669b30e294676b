#pragma once
// A run's log as CSV files for pandas, PlotJuggler, spreadsheets (RIG-4,
// docs/EXPORT.md): one file per LCM channel, one row per message, the
// nested structs flattened ("insert_cmd.state_r.state"), arrays one column
// per element ("axis_position_r[0]_m"), numbers in SI units with the unit in
// the column's name. Which columns a type has, and in which units, is known
// here and nowhere else.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hil::logger {

struct CsvChannel {
  std::string channel, type;  // "AXIS_X_CMD", "axis_setpoint_t"
  std::string file;           // the CSV file written
  bool simulated_time = false;  // first column t_s = cycle * cycle time; else log_t_s only
  int64_t rows = 0;
  int64_t skipped = 0;        // messages on it not decodable as its type
  int64_t too_wide = 0;       // messages with more columns than any rig message (an array length beyond reason)
};

struct CsvExport {
  std::vector<CsvChannel> channels;  // in the order of their first message
  // Channels none of whose messages is a type this build knows: not exported.
  std::vector<std::pair<std::string, int64_t>> unknown;  // channel, messages
  // Channels beyond the most one export writes (500; a rig log has a dozen).
  std::vector<std::pair<std::string, int64_t>> too_many;  // channel, messages
  std::optional<double> cycle_s;     // from the first HIL_MANIFEST; none: no t_s column anywhere
  int64_t messages = 0;
  std::string damage;  // where the file is not whole records (LogDamage::describe), "" if it is
};

// Writes <dir>/<channel>.csv for every channel of `log_path` whose type is
// known. Throws std::runtime_error if the file cannot be read or is not an
// LCM event log (no event in it). A damaged log is exported as far as its
// records are whole (`damage` says where it is not).
CsvExport export_csv(const std::string& log_path, const std::string& dir);

struct LogRecord;

enum class CellKind : char { number = 'n', integer = 'i', text = 't' };

// One message as the CSV writes it: its columns' names and cells (numbers
// "%.15g" in SI units, texts quoted); none if it is no type of the rig or
// does not decode.
struct MessageColumns {
  std::string type;
  bool simulated_time = false;  // its cycle is the time it belongs to (CsvChannel::simulated_time)
  int64_t cycle = 0;
  std::vector<std::string> names, cells;
  std::vector<CellKind> kinds;  // one per cell
};
std::optional<MessageColumns> message_columns(const LogRecord& record);

// A text as an RFC 4180 field: always quoted, quotes doubled.
std::string csv_quoted(const std::string& text);

}  // namespace hil::logger
