#include "log_mutation.hpp"

#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/log_summary_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/rt_stats_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <hil/scenario_text_t.hpp>
#include <hil/traffic_count_t.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>

#include "channels.hpp"
#include "fuzz_rng.hpp"
#include "run_secret.hpp"
#include "untrusted_decode.hpp"

namespace hil::fuzz {
namespace {

using logger::LogRecord;

constexpr int64_t record_header = 28;  // sync word, event number, timestamp, channel and data lengths

uint64_t get_be(const std::vector<uint8_t>& b, int64_t at, int bytes) {
  uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v = v << 8 | b[static_cast<size_t>(at + i)];
  return v;
}
void put_be(std::vector<uint8_t>& b, int64_t at, uint64_t v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i, v >>= 8) b[static_cast<size_t>(at + i)] = static_cast<uint8_t>(v);
}
void append_be(std::vector<uint8_t>& b, uint64_t v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i) b.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

int64_t fingerprint(const LogRecord& r) {
  return r.data.size() < 8 ? 0 : static_cast<int64_t>(get_be(r.data, 0, 8));
}
template <typename Message>
bool is(const LogRecord& r) {
  return fingerprint(r) == Message::getHash();
}

bool lock_step_channel(const std::string& ch) {
  return ch == channels::hli_state || ch == channels::hli_control || !channels::axis_of_command(ch).empty() ||
         !channels::axis_of_state(ch).empty();
}
// What `hil compare` compares: all but the handshake, the seal, LCM's self test.
bool compared_channel(const std::string& ch) {
  return ch != channels::participant && ch != channels::log_end && ch != channels::lcm_self_test;
}
// The cnc's output, which `hil rerun` compares byte for byte.
bool cnc_output_channel(const std::string& ch) {
  return ch == channels::hli_state || !channels::axis_of_command(ch).empty();
}

std::optional<size_t> cnc_run_end(const LogRecords& log) {
  for (size_t i = 0; i < log.records.size(); ++i) {
    const LogRecord& r = log.records[i];
    hil::participant_t m{};
    if (r.channel == channels::participant &&
        lcm_support::decode_untrusted(r.data.data(), r.data.size(), m) && m.name == "cnc" &&
        m.phase == hil::participant_t::PHASE_RUN_END)
      return i;
  }
  return std::nullopt;
}
std::optional<size_t> seal(const LogRecords& log) {
  for (size_t i = 0; i < log.records.size(); ++i)
    if (log.records[i].channel == channels::log_end) return i;
  return std::nullopt;
}

int64_t extreme_cycle(Rng& rng, int64_t real) {
  const int64_t picks[] = {1000000000000, -1000, std::numeric_limits<int64_t>::max(),
                           std::numeric_limits<int64_t>::min(), int64_t{1} << 32, int64_t{1} << 31, -1, 0,
                           real + 1, real - 1, real + 128};
  if (rng.chance(0.15)) return static_cast<int64_t>(mix_seed(static_cast<uint64_t>(rng.integer(0, 1 << 30))));
  return picks[rng.integer(0, std::size(picks) - 1)];
}

// Where each record's bytes begin in log_bytes(log).
std::vector<int64_t> offsets(const LogRecords& log) {
  std::vector<int64_t> at;
  int64_t pos = 0;
  for (const LogRecord& r : log.records) {
    at.push_back(pos);
    pos += record_header + static_cast<int64_t>(r.channel.size() + r.data.size());
  }
  at.push_back(pos);
  return at;
}

// Records of `log` that `wanted` picks, one drawn at random.
template <typename Wanted>
std::optional<size_t> pick_record(const LogRecords& log, Rng& rng, Wanted wanted) {
  std::vector<size_t> candidates;
  for (size_t i = 0; i < log.records.size(); ++i)
    if (wanted(log.records[i])) candidates.push_back(i);
  if (candidates.empty()) return std::nullopt;
  return candidates[static_cast<size_t>(rng.integer(0, static_cast<int64_t>(candidates.size()) - 1))];
}

// Whether bytes [from, to) of a payload of `size` bytes reach beyond what
// the comparisons mask: the MAC (the last field, RIG-12) for both, the run
// id (bytes 8 .. 16) for hil compare.
bool beyond_mask(int64_t from, int64_t to, int64_t size, bool run_id_masked) {
  const int64_t mac = static_cast<int64_t>(lcm_support::RunSecret::mac_bytes);
  if (size >= 16 + mac && from >= size - mac) return false;
  return !(run_id_masked && size >= 16 + mac && from >= 8 && to <= 16);
}

// The oracles of a change to the payload of record `r`, bytes [from, to).
void payload_oracles(Mutant& m, const LogRecord& r, int64_t from, int64_t to) {
  const int64_t size = static_cast<int64_t>(r.data.size());
  m.must_differ = m.must_differ || (compared_channel(r.channel) && beyond_mask(from, to, size, true));
  m.must_rerun_differ = m.must_rerun_differ || (cnc_output_channel(r.channel) && beyond_mask(from, to, size, false));
}

Mutant from_records(MutationKind kind, const LogRecords& original, const LogRecords& changed, std::string what) {
  Mutant m;
  m.kind = kind;
  m.what = std::move(what);
  m.bytes = log_bytes(changed);
  m.changed = m.bytes != log_bytes(original);
  return m;
}

Mutant truncate(const LogRecords& log, Rng& rng) {
  Mutant m;
  m.kind = MutationKind::truncate;
  m.bytes = log_bytes(log);
  const std::vector<int64_t> at = offsets(log);
  const int64_t cut = rng.integer(0, static_cast<int64_t>(m.bytes.size()) - 1);
  m.bytes.resize(static_cast<size_t>(cut));
  m.what = "cut at byte " + std::to_string(cut) + " of " + std::to_string(at.back());
  m.must_fail = true;  // the seal is the last record: a cut log has none
  const bool mid_record = std::find(at.begin(), at.end(), cut) == at.end();
  m.must_differ = mid_record;  // a damaged file differs from any log
  m.must_rerun_differ = mid_record;
  for (size_t i = 0; i < log.records.size(); ++i)
    if (at[i] >= cut) {
      m.must_differ = m.must_differ || compared_channel(log.records[i].channel);
      m.must_rerun_differ = m.must_rerun_differ || cnc_output_channel(log.records[i].channel);
    }
  return m;
}

Mutant flip_bytes(const LogRecords& log, Rng& rng) {
  Mutant m;
  m.kind = MutationKind::flip_bytes;
  m.bytes = log_bytes(log);
  const std::vector<int64_t> at = offsets(log);
  const int flips = static_cast<int>(rng.integer(1, 4));
  for (int k = 0; k < flips; ++k) {
    const int64_t pos = rng.integer(0, static_cast<int64_t>(m.bytes.size()) - 1);
    m.bytes[static_cast<size_t>(pos)] ^= static_cast<uint8_t>(1u << rng.integer(0, 7));
    const size_t i = static_cast<size_t>(std::upper_bound(at.begin(), at.end(), pos) - at.begin() - 1);
    const LogRecord& r = log.records[i];
    const int64_t in_record = pos - at[i];
    const int64_t channel_end = record_header + static_cast<int64_t>(r.channel.size());
    m.what += (m.what.empty() ? "" : ", ") + std::string("byte ") + std::to_string(pos) + " (" + r.channel +
              " record " + std::to_string(i) + ", byte " + std::to_string(in_record) + ")";
    if (in_record < 4 || (in_record >= 20 && in_record < record_header)) {
      // The framing (sync word, lengths): the file is damaged.
      m.must_fail = m.must_differ = m.must_rerun_differ = true;
    } else if (in_record >= record_header && in_record < channel_end) {
      // The channel's name: the message is on a channel of no rig (compared).
      m.must_fail = m.must_differ = true;
      m.must_rerun_differ = m.must_rerun_differ || cnc_output_channel(r.channel);
    } else if (in_record >= channel_end) {
      const int64_t in_data = in_record - channel_end;
      // Its fingerprint (no longer its type), or the cycle of a lock-step message.
      if (in_data < 8 || (in_data >= 24 && in_data < 32 && lock_step_channel(r.channel))) m.must_fail = true;
      payload_oracles(m, r, in_data, in_data + 1);
    }
  }
  return m;
}

Mutant insert_garbage(const LogRecords& log, Rng& rng) {
  Mutant m;
  m.kind = MutationKind::insert_garbage;
  m.bytes = log_bytes(log);
  const int64_t pos = rng.integer(0, static_cast<int64_t>(m.bytes.size()));
  std::vector<uint8_t> garbage(static_cast<size_t>(rng.integer(1, 64)));
  for (uint8_t& b : garbage) b = static_cast<uint8_t>(rng.integer(0, 255));
  m.bytes.insert(m.bytes.begin() + pos, garbage.begin(), garbage.end());
  m.what = std::to_string(garbage.size()) + " random byte(s) at byte " + std::to_string(pos);
  m.must_fail = m.must_differ = m.must_rerun_differ = true;  // bytes that are no record: a damaged file
  return m;
}

Mutant run_end_cycle(const LogRecords& log, Rng& rng, bool forge) {
  const MutationKind kind = forge ? MutationKind::forged_run_end : MutationKind::run_end_cycle;
  const std::optional<size_t> end = cnc_run_end(log);
  if (!end) return from_records(kind, log, log, "no cnc RUN_END to change");
  LogRecords changed = log;
  LogRecord record = log.records[*end];
  const int64_t real = static_cast<int64_t>(get_be(record.data, 24, 8));
  int64_t cycle = extreme_cycle(rng, real);
  if (cycle == real) cycle = real + 1;
  put_be(record.data, 24, static_cast<uint64_t>(cycle), 8);
  std::string what = "cnc RUN_END cycle " + std::to_string(real) + " -> " + std::to_string(cycle);
  if (forge) {
    const size_t before = seal(log).value_or(log.records.size());
    const size_t at = static_cast<size_t>(rng.integer(static_cast<int64_t>(*end) + 1, static_cast<int64_t>(before)));
    changed.records.insert(changed.records.begin() + static_cast<std::ptrdiff_t>(at), record);
    what = "a forged " + what + " inserted as record " + std::to_string(at);
  } else {
    changed.records[*end] = record;
  }
  Mutant m = from_records(kind, log, changed, what);
  m.must_fail = true;
  return m;
}

Mutant message_cycle(const LogRecords& log, Rng& rng) {
  LogRecords changed = log;
  const auto i = pick_record(log, rng, [](const LogRecord& r) { return r.data.size() >= 32; });
  if (!i) return from_records(MutationKind::message_cycle, log, log, "no message");
  LogRecord& r = changed.records[*i];
  const int64_t real = static_cast<int64_t>(get_be(r.data, 24, 8));
  const int64_t cycle = extreme_cycle(rng, real);
  put_be(r.data, 24, static_cast<uint64_t>(cycle), 8);
  Mutant m = from_records(MutationKind::message_cycle, log, changed,
                          r.channel + " record " + std::to_string(*i) + ": cycle " + std::to_string(real) + " -> " +
                              std::to_string(cycle));
  m.must_fail = lock_step_channel(r.channel);
  payload_oracles(m, r, 24, 32);
  return m;
}

Mutant length_field(const LogRecords& log, Rng& rng, bool array) {
  const MutationKind kind = array ? MutationKind::array_length : MutationKind::string_length;
  auto fields = [array](const LogRecord& r) {
    const FieldMap f = field_map(r);
    return array ? f.array_lengths : f.string_lengths;
  };
  const auto i = pick_record(log, rng, [&](const LogRecord& r) { return !fields(r).empty(); });
  if (!i) return from_records(kind, log, log, "no such field");
  LogRecords changed = log;
  LogRecord& r = changed.records[*i];
  const std::vector<int64_t> at = fields(r);
  const int64_t off = at[static_cast<size_t>(rng.integer(0, static_cast<int64_t>(at.size()) - 1))];
  const int bytes = array ? 2 : 4;
  const int64_t real = array ? static_cast<int16_t>(get_be(r.data, off, 2)) : static_cast<int32_t>(get_be(r.data, off, 4));
  const int64_t array_picks[] = {-1, -32768, 32767, real + 1, real > 0 ? real - 1 : 2};
  const int64_t string_picks[] = {std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::min() + 1, -1, 0,
                                  std::numeric_limits<int32_t>::max(), real + 1, real > 1 ? real - 1 : 3};
  const int64_t value = array ? array_picks[rng.integer(0, std::size(array_picks) - 1)]
                              : string_picks[rng.integer(0, std::size(string_picks) - 1)];
  put_be(r.data, off, static_cast<uint64_t>(value), bytes);
  Mutant m = from_records(kind, log, changed,
                          r.channel + " record " + std::to_string(*i) + ": the " + (array ? "array" : "string") +
                              " length at byte " + std::to_string(off) + " " + std::to_string(real) + " -> " +
                              std::to_string(value));
  m.must_fail = true;  // no longer its type: undecodable
  payload_oracles(m, r, off, off + bytes);
  return m;
}

Mutant not_finite(const LogRecords& log, Rng& rng) {
  const auto i = pick_record(log, rng, [](const LogRecord& r) { return !field_map(r).positions.empty(); });
  if (!i) return from_records(MutationKind::not_finite, log, log, "no axis message");
  LogRecords changed = log;
  LogRecord& r = changed.records[*i];
  const int64_t off = field_map(r).positions.front();
  const double picks[] = {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  const double value = picks[rng.integer(0, 2)];
  uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  put_be(r.data, off, bits, 8);
  Mutant m = from_records(MutationKind::not_finite, log, changed,
                          r.channel + " record " + std::to_string(*i) + ": position " + std::to_string(value));
  m.must_fail = true;  // the limit check fails a position that is not finite
  payload_oracles(m, r, off, off + 8);
  return m;
}

Mutant duplicate_or_drop(const LogRecords& log, Rng& rng, bool duplicate) {
  const MutationKind kind = duplicate ? MutationKind::duplicate_record : MutationKind::drop_record;
  LogRecords changed = log;
  const size_t i = static_cast<size_t>(rng.integer(0, static_cast<int64_t>(log.records.size()) - 1));
  const LogRecord& r = log.records[i];
  std::string what;
  if (duplicate) {
    const size_t to = static_cast<size_t>(rng.chance(0.5) ? static_cast<int64_t>(i) + 1
                                                          : rng.integer(0, static_cast<int64_t>(log.records.size())));
    changed.records.insert(changed.records.begin() + static_cast<std::ptrdiff_t>(to), r);
    what = r.channel + " record " + std::to_string(i) + " again as record " + std::to_string(to);
  } else {
    changed.records.erase(changed.records.begin() + static_cast<std::ptrdiff_t>(i));
    what = r.channel + " record " + std::to_string(i) + " left out";
  }
  Mutant m = from_records(kind, log, changed, what);
  m.must_fail = true;  // the seal counts the records before it, and is the last
  m.must_differ = compared_channel(r.channel);
  m.must_rerun_differ = cnc_output_channel(r.channel);
  return m;
}

Mutant reorder(const LogRecords& log, Rng& rng) {
  LogRecords changed = log;
  const int64_t n = static_cast<int64_t>(log.records.size());
  const size_t i = static_cast<size_t>(rng.integer(0, n - 1));
  // Near each other mostly (as a network reorders), anywhere sometimes.
  const size_t j = static_cast<size_t>(rng.chance(0.7) ? std::clamp<int64_t>(static_cast<int64_t>(i) + rng.integer(-8, 8), 0, n - 1)
                                                       : rng.integer(0, n - 1));
  std::swap(changed.records[i], changed.records[j]);
  const LogRecord &a = log.records[i], &b = log.records[j];
  Mutant m = from_records(MutationKind::reorder_records, log, changed,
                          "records " + std::to_string(i) + " (" + a.channel + ") and " + std::to_string(j) + " (" +
                              b.channel + ") swapped");
  m.must_fail = a.channel == channels::log_end || b.channel == channels::log_end;  // the seal no longer last
  // Two messages of one channel swapped differ to the comparisons if they
  // differ beyond the masks (events: hil compare takes them as a set).
  if (a.channel == b.channel && a.data.size() == b.data.size()) {
    bool beyond_compare = false, beyond_rerun = false;
    for (size_t k = 0; k < a.data.size(); ++k)
      if (a.data[k] != b.data[k]) {
        const int64_t at = static_cast<int64_t>(k), size = static_cast<int64_t>(a.data.size());
        beyond_compare = beyond_compare || beyond_mask(at, at + 1, size, true);
        beyond_rerun = beyond_rerun || beyond_mask(at, at + 1, size, false);
      }
    m.must_differ = compared_channel(a.channel) && a.channel != channels::event && beyond_compare;
    m.must_rerun_differ = cnc_output_channel(a.channel) && beyond_rerun;
  } else if (a.channel == b.channel) {
    m.must_differ = compared_channel(a.channel) && a.channel != channels::event;
    m.must_rerun_differ = cnc_output_channel(a.channel);
  }
  return m;
}

Mutant rename(const LogRecords& log, Rng& rng) {
  LogRecords changed = log;
  const size_t i = static_cast<size_t>(rng.integer(0, static_cast<int64_t>(log.records.size()) - 1));
  LogRecord& r = changed.records[i];
  const std::string old = r.channel;
  std::vector<std::string> rig;  // the log's other channels
  for (const LogRecord& other : log.records)
    if (other.channel != old && std::find(rig.begin(), rig.end(), other.channel) == rig.end()) rig.push_back(other.channel);
  switch (rng.integer(0, 4)) {
    case 0: r.channel = "FUZZ_" + std::to_string(rng.integer(0, 999999)); break;  // not the rig's
    case 1: r.channel = std::string(logger::EventLogReader::max_channel_length, 'Q'); break;
    case 2: r.channel = rig.empty() ? "AXIS_Q_CMD" : rig[static_cast<size_t>(rng.integer(0, static_cast<int64_t>(rig.size()) - 1))]; break;
    case 3: r.channel = old + std::string(1, '\0') + "x"; break;  // a NUL inside: not the name it begins with
    default: r.channel = "AXIS_Q" + old.substr(std::min<size_t>(old.size(), 6)); break;  // an axis the machine lacks
  }
  std::string shown = r.channel.size() > 40 ? r.channel.substr(0, 12) + "... (" + std::to_string(r.channel.size()) +
                                                  " characters)"
                                            : r.channel;
  if (const size_t nul = shown.find('\0'); nul != std::string::npos) shown.replace(nul, 1, "\\0");
  Mutant m = from_records(MutationKind::rename_channel, log, changed, "record " + std::to_string(i) + ": " + old + " -> " + shown);
  m.must_fail = true;  // its message is missing where it was, and undecodable or a repeated cycle where it is now
  m.must_differ = compared_channel(old) || compared_channel(r.channel);
  m.must_rerun_differ = cnc_output_channel(old) || cnc_output_channel(r.channel);
  return m;
}

Mutant whole_file(MutationKind kind, Rng& rng) {
  Mutant m;
  m.kind = kind;
  m.must_fail = m.must_differ = m.must_rerun_differ = true;
  if (kind == MutationKind::empty_file) {
    m.what = "0 bytes";
    return m;
  }
  m.bytes.resize(static_cast<size_t>(rng.integer(1, 4096)));
  for (uint8_t& b : m.bytes) b = static_cast<uint8_t>(rng.integer(0, 255));
  for (size_t k = 0; k + 4 <= m.bytes.size(); ++k)  // no sync word by chance
    if (m.bytes[k] == 0xED && m.bytes[k + 1] == 0xA1 && m.bytes[k + 2] == 0xDA && m.bytes[k + 3] == 0x01) m.bytes[k] = 0;
  m.what = std::to_string(m.bytes.size()) + " random bytes";
  return m;
}

}  // namespace

const char* name_of(MutationKind kind) {
  static const char* names[] = {"truncate",      "flip_bytes",       "insert_garbage", "run_end_cycle",
                                "forged_run_end", "message_cycle",   "array_length",   "string_length",
                                "not_finite",    "duplicate_record", "drop_record",    "reorder_records",
                                "rename_channel", "empty_file",      "not_a_log"};
  static_assert(std::size(names) == mutation_kinds);
  return names[static_cast<int>(kind)];
}

LogRecords read_records(const std::string& path) {
  logger::EventLogReader reader(path);
  LogRecords log;
  while (const LogRecord* r = reader.next()) log.records.push_back(*r);
  if (reader.damage().any()) throw std::runtime_error(path + " is damaged: " + reader.damage().describe());
  return log;
}

std::vector<uint8_t> log_bytes(const LogRecords& log) {
  std::vector<uint8_t> out;
  int64_t number = 0;
  for (const LogRecord& r : log.records) {
    append_be(out, 0xEDA1DA01, 4);
    append_be(out, static_cast<uint64_t>(number++), 8);
    append_be(out, static_cast<uint64_t>(r.timestamp), 8);
    append_be(out, r.channel.size(), 4);
    append_be(out, r.data.size(), 4);
    out.insert(out.end(), r.channel.begin(), r.channel.end());
    out.insert(out.end(), r.data.begin(), r.data.end());
  }
  return out;
}

Mutant mutate(const LogRecords& log, Rng& rng) {
  return mutate(log, rng, static_cast<MutationKind>(rng.integer(0, mutation_kinds - 1)));
}

Mutant mutate(const LogRecords& log, Rng& rng, MutationKind kind) {
  switch (kind) {
    case MutationKind::truncate: return truncate(log, rng);
    case MutationKind::flip_bytes: return flip_bytes(log, rng);
    case MutationKind::insert_garbage: return insert_garbage(log, rng);
    case MutationKind::run_end_cycle: return run_end_cycle(log, rng, false);
    case MutationKind::forged_run_end: return run_end_cycle(log, rng, true);
    case MutationKind::message_cycle: return message_cycle(log, rng);
    case MutationKind::array_length: return length_field(log, rng, true);
    case MutationKind::string_length: return length_field(log, rng, false);
    case MutationKind::not_finite: return not_finite(log, rng);
    case MutationKind::duplicate_record: return duplicate_or_drop(log, rng, true);
    case MutationKind::drop_record: return duplicate_or_drop(log, rng, false);
    case MutationKind::reorder_records: return reorder(log, rng);
    case MutationKind::rename_channel: return rename(log, rng);
    case MutationKind::empty_file:
    case MutationKind::not_a_log: return whole_file(kind, rng);
  }
  throw std::logic_error("unknown mutation kind");
}

FieldMap field_map(const LogRecord& r) {
  FieldMap f;
  const int64_t size = static_cast<int64_t>(r.data.size());
  if (size < 32) return f;
  f.cycle = 24;
  // A string's int32 length field at `at` counts its bytes and a NUL.
  auto after_string = [&](int64_t at) -> int64_t {
    if (at < 0 || at + 4 > size) return -1;
    const int64_t length = static_cast<int32_t>(get_be(r.data, at, 4));
    return length < 0 || at + 4 + length > size ? -1 : at + 4 + length;
  };
  auto add = [&](std::vector<int64_t>& to, int64_t at, int bytes) {
    if (at >= 0 && at + bytes <= size) to.push_back(at);
  };
  if (is<hil::axis_setpoint_t>(r)) {
    add(f.string_lengths, 32, 4);
    add(f.positions, after_string(32), 8);  // position
  } else if (is<hil::axis_state_t>(r)) {
    add(f.string_lengths, 32, 4);
    const int64_t setpoint = after_string(32);
    add(f.positions, setpoint < 0 ? -1 : setpoint + 8, 8);  // position, after setpoint_position
  } else if (is<hil::participant_t>(r)) {
    add(f.string_lengths, 32, 4);
    const int64_t name_end = after_string(32);
    if (name_end < 0) return f;
    const int64_t n_rejected = name_end + 1 + 4;  // phase, verdicts
    add(f.array_lengths, n_rejected, 2);
    if (n_rejected + 2 > size) return f;
    hil::traffic_count_t empty{};
    const int64_t counts_bytes = empty._getEncodedSizeNoHash() - 4 - 1;  // its int64 counts, after the channel
    int64_t at = n_rejected + 2;
    for (int64_t k = static_cast<int16_t>(get_be(r.data, n_rejected, 2)); k > 0 && at >= 0; --k) {
      at = after_string(at);
      if (at >= 0) at += counts_bytes;
    }
    add(f.array_lengths, at, 2);  // n_lost
  } else if (is<hil::run_manifest_t>(r)) {
    add(f.string_lengths, 32, 4);
    const int64_t version_end = after_string(32);
    add(f.string_lengths, version_end, 4);
    const int64_t name_end = after_string(version_end);
    add(f.array_lengths, name_end < 0 ? -1 : name_end + 4 + 4 + 8 + 8, 2);  // cycle_us .. scenario_digest
  } else if (is<hil::rt_stats_t>(r)) {
    add(f.string_lengths, 32 + 1 + 4, 4);
    const int64_t scheduling_end = after_string(37);
    add(f.array_lengths, scheduling_end < 0 ? -1 : scheduling_end + 5 * 8, 2);  // ticks .. jitter_max_us
  } else if (is<hil::log_summary_t>(r)) {
    add(f.array_lengths, 32 + 8 + 8, 2);  // recorded, socket_drops, n_missing
  } else if (is<hil::hli_state_t>(r)) {
    add(f.array_lengths, 32 + 1 + 8 + 8 + 4 + 8 + 8 + 4, 2);  // channel_state .. last_error_id, n_axes
  } else if (is<hil::event_t>(r)) {
    add(f.string_lengths, 32 + 1 + 1 + 4, 4);  // severity, verdict, id, parameter
  } else if (is<hil::scenario_text_t>(r)) {
    add(f.string_lengths, 32 + 8, 4);  // digest, yaml
  }
  return f;
}

std::string check_field_map(const LogRecord& r) {
  const FieldMap f = field_map(r);
  if (f.cycle < 0) return "";
  std::vector<int64_t> arrays, strings;  // what lcm-gen decodes, in the order of the map
  std::optional<double> position;
  auto decoded = [&](auto& m) { return lcm_support::decode_untrusted(r.data.data(), r.data.size(), m); };
  bool known = true;
  if (hil::axis_setpoint_t m{}; is<hil::axis_setpoint_t>(r) && decoded(m)) {
    strings = {static_cast<int64_t>(m.axis.size())};
    position = m.position;
  } else if (hil::axis_state_t m{}; is<hil::axis_state_t>(r) && decoded(m)) {
    strings = {static_cast<int64_t>(m.axis.size())};
    position = m.position;
  } else if (hil::participant_t m{}; is<hil::participant_t>(r) && decoded(m)) {
    strings = {static_cast<int64_t>(m.name.size())};
    arrays = {m.n_rejected, m.n_lost};
  } else if (hil::run_manifest_t m{}; is<hil::run_manifest_t>(r) && decoded(m)) {
    strings = {static_cast<int64_t>(m.rig_version.size()), static_cast<int64_t>(m.scenario_name.size())};
    arrays = {m.n_participants};
  } else if (hil::rt_stats_t m{}; is<hil::rt_stats_t>(r) && decoded(m)) {
    strings = {static_cast<int64_t>(m.scheduling.size())};
    arrays = {m.n_participants};
  } else if (hil::log_summary_t m{}; is<hil::log_summary_t>(r) && decoded(m)) {
    arrays = {m.n_missing};
  } else if (hil::hli_state_t m{}; is<hil::hli_state_t>(r) && decoded(m)) {
    arrays = {m.n_axes};
  } else if (hil::event_t m{}; is<hil::event_t>(r) && decoded(m)) {
    strings = {static_cast<int64_t>(m.parameter.size())};
  } else if (hil::scenario_text_t m{}; is<hil::scenario_text_t>(r) && decoded(m)) {
    strings = {static_cast<int64_t>(m.yaml.size())};
  } else {
    known = false;
  }
  if (!known) return "";
  std::string wrong;
  if (f.array_lengths.size() != arrays.size()) wrong += " array lengths found " + std::to_string(f.array_lengths.size());
  for (size_t k = 0; k < std::min(arrays.size(), f.array_lengths.size()); ++k)
    if (static_cast<int16_t>(get_be(r.data, f.array_lengths[k], 2)) != arrays[k])
      wrong += " array length " + std::to_string(k) + " at byte " + std::to_string(f.array_lengths[k]);
  if (f.string_lengths.size() != strings.size()) wrong += " string lengths found " + std::to_string(f.string_lengths.size());
  for (size_t k = 0; k < std::min(strings.size(), f.string_lengths.size()); ++k)
    if (static_cast<int32_t>(get_be(r.data, f.string_lengths[k], 4)) != strings[k] + 1)
      wrong += " string length " + std::to_string(k) + " at byte " + std::to_string(f.string_lengths[k]);
  if (position) {
    double at = std::nan("");
    if (!f.positions.empty()) {
      const uint64_t bits = get_be(r.data, f.positions.front(), 8);
      std::memcpy(&at, &bits, sizeof at);
    }
    if (!(at == *position)) wrong += " position";
  }
  return wrong.empty() ? "" : r.channel + ":" + wrong;
}

}  // namespace hil::fuzz
