#pragma once
// Errors and warnings are values (KRN-2): raised by the library that detects
// them, carried to the HLI and the log by the nodes.
#include <cstdint>
#include <string>

namespace hil {

enum class Severity : int8_t { info = 0, warning = 1, error = 2 };

// An expectation's outcome (RIG-5): the PLC simulator's events carry it, so
// the rig counts them without reading the message; other events have none.
enum class Verdict : int8_t { none = 0, pass = 1, fail = 2 };

struct Event {
  Severity severity = Severity::error;
  int32_t id = 0;             // TF5200 error/warning number, 0 = none documented
  std::string parameter;      // e.g. "P-AXIS-00442"
  std::string axis;
  int64_t nc_line = 0;        // 1-based NC program line, 0 = not from the program
  int64_t block_nr = 0;       // N number, 0 = none
  double value = 0.0;
  double limit = 0.0;
  std::string message;
  Verdict verdict = Verdict::none;
  int64_t column = 0;  // 1-based column of a refused word in its NC line, 0 = not known (not on the bus)
};

const char* to_string(Severity severity);

// One line for people: "error 0 line 7 N40: unknown G code G17".
std::string describe(const Event& event);

}  // namespace hil
