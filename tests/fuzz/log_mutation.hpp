#pragma once
// The log fuzz's mutations (RIG-4, RIG-9): a real run's LCM event log made
// into a crafted one, seeded. Each mutant says what it did and what its
// readers must then conclude: a mutation that takes, adds or changes the
// run's own messages in a way the log shows must never be judged PASS,
// and one on a channel `hil compare` compares must never compare identical.
#include <cstdint>
#include <string>
#include <vector>

#include "event_log_reader.hpp"

namespace hil::fuzz {

class Rng;

enum class MutationKind {
  truncate,          // the file cut at a random byte
  flip_bytes,        // 1 .. 4 bytes anywhere get a random bit flipped
  insert_garbage,    // random bytes inserted anywhere
  run_end_cycle,     // the cnc's RUN_END names another cycle (extremes: 10^12, -1000, INT64_MAX, 2^32 ...)
  forged_run_end,    // a second cnc RUN_END, of another cycle, before the seal (the forgery)
  message_cycle,     // a message's cycle set to an extreme
  array_length,      // an array length field (n_axes, n_lost, n_participants ...) set to -1, -32768, 32767, n +- 1
  string_length,     // a string length field set to -2^31, -1, 0, 2^31 - 1, len + 1
  not_finite,        // an axis position NaN or +-inf
  duplicate_record,  // a record written twice
  drop_record,       // a record left out
  reorder_records,   // two records swapped
  rename_channel,    // a record's channel renamed (not the rig's, 999 characters, another rig channel)
  empty_file,        // 0 bytes
  not_a_log,         // bytes without a single LCM event
};
const char* name_of(MutationKind kind);
constexpr int mutation_kinds = 15;

// A log as its records, to mutate and write again.
struct LogRecords {
  std::vector<logger::LogRecord> records;
};
LogRecords read_records(const std::string& path);  // throws if the log is damaged
std::vector<uint8_t> log_bytes(const LogRecords& log);  // LCM's event log format, event numbers in order

struct Mutant {
  MutationKind kind = MutationKind::truncate;
  std::string what;  // "AXIS_X_CMD record 17: cycle 16 -> 9223372036854775807"
  std::vector<uint8_t> bytes;
  bool changed = true;       // false: the mutation happened to change nothing (the oracles do not apply)
  bool must_fail = false;    // the verdict must not PASS
  bool must_differ = false;  // hil compare against the original must not say identical
  bool must_rerun_differ = false;  // hil rerun must not say identical (the cnc's own output changed)
};

// One seeded mutation of `log`, of a kind drawn by `rng` (or the one given).
Mutant mutate(const LogRecords& log, Rng& rng);
Mutant mutate(const LogRecords& log, Rng& rng, MutationKind kind);

// Where in a rig message's bytes its fields sit, as far as the mutations
// need them (lcmtypes/: fingerprint, run_id, utime, cycle come first).
// Offsets of -1: the type has no such field. Checked against lcm-gen's
// decoding of every record of the fuzz's base logs (check_field_map).
struct FieldMap {
  int64_t cycle = -1;
  std::vector<int64_t> string_lengths;  // int32 length fields of strings
  std::vector<int64_t> array_lengths;   // int16 length fields of arrays
  std::vector<int64_t> positions;       // doubles the limit check must see finite
};
FieldMap field_map(const logger::LogRecord& record);
// "" if the field map agrees with what lcm-gen decodes from the record,
// else what differs (lcmtypes/ changed: update log_mutation.cpp).
std::string check_field_map(const logger::LogRecord& record);

}  // namespace hil::fuzz
