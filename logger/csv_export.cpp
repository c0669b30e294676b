#include "csv_export.hpp"

#include <hil/axis_setpoint_t.hpp>
#include <hil/axis_state_t.hpp>
#include <hil/event_t.hpp>
#include <hil/hli_control_t.hpp>
#include <hil/hli_state_t.hpp>
#include <hil/log_summary_t.hpp>
#include <hil/participant_t.hpp>
#include <hil/rt_stats_t.hpp>
#include <hil/run_manifest_t.hpp>
#include <hil/scenario_text_t.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include "event_log_reader.hpp"
#include "hli.hpp"
#include "untrusted_decode.hpp"

namespace hil::logger {
namespace {

namespace fs = std::filesystem;

// One message as columns: the names always, the cells unless only the
// header is wanted (the first pass).
class Row {
 public:
  explicit Row(bool names_only) : names_only_(names_only) {}
  void number(const std::string& name, double value) {
    names_.push_back(name);
    if (names_only_) return;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.15g", value);  // 15 digits: no round-off noise from the unit conversion
    cells_.emplace_back(buf);
    kinds_.push_back(CellKind::number);
  }
  void integer(const std::string& name, int64_t value) {
    names_.push_back(name);
    if (names_only_) return;
    cells_.push_back(std::to_string(value));
    kinds_.push_back(CellKind::integer);
  }
  void flag(const std::string& name, bool value) { integer(name, value ? 1 : 0); }
  void text(const std::string& name, const std::string& value) {
    names_.push_back(name);
    if (names_only_) return;
    cells_.push_back(csv_quoted(value));
    kinds_.push_back(CellKind::text);
  }
  const std::vector<std::string>& names() const { return names_; }
  const std::vector<std::string>& cells() const { return cells_; }
  const std::vector<CellKind>& kinds() const { return kinds_; }
  int64_t cycle = 0;

 private:
  bool names_only_;
  std::vector<std::string> names_, cells_;
  std::vector<CellKind> kinds_;
};

std::string at(const std::string& name, size_t i) { return name + "[" + std::to_string(i) + "]"; }

// A length on an axis in SI: A, B, C are rotary and count in degrees where
// the rig says mm (docs/UNITS.md, as rig/report.cpp names them).
struct Length {
  std::string unit;  // "m" or "rad"
  double si;         // SI per mm (deg)
};
Length length_of(const std::string& axis) {
  if (axis.find_first_of("ABC") == 0) return {"rad", M_PI / 180};
  return {"m", 1e-3};
}
constexpr double hli_unit_m = 1e-3 / hli_units_per_mm;  // the HLI's 0.1 um
constexpr double override_unit = 1e-3;                  // the HLI's 0.1 % as a ratio (1 = 100 %)

template <typename Message>
void head(Row& r, const Message& m) {
  r.cycle = m.cycle;
  r.integer("run_id", m.run_id);
  r.number("utime_s", m.utime * 1e-6);
  r.integer("cycle", m.cycle);
}

void unit(Row& r, const std::string& p, const hil::hli_control_unit_bool_t& u) {
  r.flag(p + ".command_w", u.command_w);
  r.flag(p + ".enable_w", u.enable_w);
}
void unit(Row& r, const std::string& p, const hil::hli_control_unit_state_t& u) {
  r.flag(p + ".request_r", u.request_r);
  r.flag(p + ".state_r", u.state_r);
}

void traffic(Row& r, const std::vector<hil::traffic_count_t>& counts) {
  for (size_t i = 0; i < counts.size(); ++i) {
    const std::string p = at("rejected", i);
    r.text(p + ".channel", counts[i].channel);
    r.integer(p + ".foreign_run", counts[i].foreign_run);
    r.integer(p + ".wrong_cycle", counts[i].wrong_cycle);
    r.integer(p + ".undecodable", counts[i].undecodable);
    r.integer(p + ".unauthenticated", counts[i].unauthenticated);
    r.integer(p + ".oversized", counts[i].oversized);
  }
}

void columns(Row& r, const hil::axis_setpoint_t& m) {
  head(r, m);
  r.text("axis", m.axis);
  const Length l = length_of(m.axis);
  r.number("position_" + l.unit, m.position * l.si);
  r.number("velocity_" + l.unit + "_s", m.velocity * l.si);
  r.number("acceleration_" + l.unit + "_s2", m.acceleration * l.si);
}

void columns(Row& r, const hil::axis_state_t& m) {
  head(r, m);
  r.text("axis", m.axis);
  const Length l = length_of(m.axis);
  r.number("setpoint_position_" + l.unit, m.setpoint_position * l.si);
  r.number("position_" + l.unit, m.position * l.si);
  r.number("modulo_position_" + l.unit, m.modulo_position * l.si);
  r.number("velocity_" + l.unit + "_s", m.velocity * l.si);
  r.number("acceleration_" + l.unit + "_s2", m.acceleration * l.si);
  r.number("following_error_" + l.unit, m.following_error * l.si);
  r.integer("warnings", m.warnings);
  r.integer("errors", m.errors);
}

void columns(Row& r, const hil::event_t& m) {
  head(r, m);
  r.integer("severity", m.severity);
  r.integer("verdict", m.verdict);
  r.integer("id", m.id);
  r.text("parameter", m.parameter);
  r.text("source", m.source);
  r.text("axis", m.axis);
  r.integer("nc_line", m.nc_line);
  r.integer("block_nr", m.block_nr);
  r.number("value", m.value);  // in the unit the message names
  r.number("limit", m.limit);
  r.text("message", m.message);
}

// Per axis, what follows a per-axis field's name: ".X" by the axis' name,
// "[i]" where the name is not a plain one or not the only one so named.
std::vector<std::string> axis_suffixes(const std::vector<std::string>& names, size_t count) {
  std::unordered_map<std::string, int> seen;
  for (const std::string& name : names) ++seen[name];
  std::vector<std::string> out;
  for (size_t i = 0; i < count; ++i) {
    const std::string* name = i < names.size() ? &names[i] : nullptr;
    const bool plain = name && !name->empty() && name->size() <= 16 && seen[*name] == 1 &&
                       std::all_of(name->begin(), name->end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
    out.push_back(plain ? "." + *name : "[" + std::to_string(i) + "]");
  }
  return out;
}

void columns(Row& r, const hil::hli_state_t& m) {
  head(r, m);
  r.integer("channel_state", m.channel_state);
  r.text("channel_state_name", m.channel_state >= 0 && m.channel_state <= 3
                                   ? to_string(static_cast<ChannelState>(m.channel_state))
                                   : std::to_string(m.channel_state));
  r.integer("block_nr_r", m.block_nr_r);
  r.integer("block_count_r", m.block_count_r);
  r.integer("stop_conditions_r", m.stop_conditions_r);
  r.text("stop_conditions_r_names", stop_conditions_text(m.stop_conditions_r));
  r.number("dist_prog_start_m", m.dist_prog_start * hli_unit_m);
  r.number("path_velocity_m_s", m.path_velocity * 1e-3);
  r.integer("last_error_id", m.last_error_id);
  r.integer("n_axes", m.n_axes);
  for (size_t i = 0; i < m.axis_name.size(); ++i) r.text(at("axis_name", i), m.axis_name[i]);
  const std::vector<std::string> axis = axis_suffixes(
      m.axis_name, std::max({m.axis_position_r.size(), m.lift_active.size(), m.lift_suppressed.size()}));
  for (size_t i = 0; i < m.axis_position_r.size(); ++i) {
    const Length l = length_of(i < m.axis_name.size() ? m.axis_name[i] : "");
    r.number("axis_position_r" + axis[i] + "_" + l.unit, m.axis_position_r[i] * (l.si / hli_units_per_mm));
  }
  for (size_t i = 0; i < m.lift_active.size(); ++i) r.flag("lift_active" + axis[i], m.lift_active[i]);
  for (size_t i = 0; i < m.lift_suppressed.size(); ++i) r.flag("lift_suppressed" + axis[i], m.lift_suppressed[i]);
  unit(r, "program_start", m.program_start);
  unit(r, "feedhold", m.feedhold);
  r.flag("override.request_r", m.override.request_r);
  r.number("override.state_r_ratio", m.override.state_r * override_unit);
  unit(r, "delete_distance_to_go", m.delete_distance_to_go);
  r.flag("delete_distance_to_go_activation.request_r", m.delete_distance_to_go_activation.request_r);
  r.integer("delete_distance_to_go_activation.state_r", m.delete_distance_to_go_activation.state_r);
  r.flag("delete_distance_to_go_active_r", m.delete_distance_to_go_active_r);
  r.flag("m_function_request_r", m.m_function_request_r);
  r.integer("m_function_nr_r", m.m_function_nr_r);
  r.integer("m_function_add_nr_r", m.m_function_add_nr_r);
  r.flag("h_function_request_r", m.h_function_request_r);
  r.integer("h_function_nr_r", m.h_function_nr_r);
  r.flag("s_function_request_r", m.s_function_request_r);
  r.number("s_function_value_r", m.s_function_value_r);
  r.flag("t_function_request_r", m.t_function_request_r);
  r.integer("t_function_nr_r", m.t_function_nr_r);
  r.integer("tool_offset_nr_r", m.tool_offset_nr_r);
  unit(r, "backward_motion", m.backward_motion);
  const auto& insert = m.insert_cmd;
  r.flag("insert_cmd.semaphor_rw", insert.semaphor_rw);
  r.number("insert_cmd.state_r.distance_of_next_stop_m", insert.state_r.distance_of_next_stop * hli_unit_m);
  for (size_t i = 0; i < 3; ++i)
    r.number(at("insert_cmd.state_r.position_at_next_stop", i) + "_m",
             insert.state_r.position_at_next_stop[i] * hli_unit_m);
  r.integer("insert_cmd.state_r.state", insert.state_r.state);
  unit(r, "continue_motion", m.continue_motion);
  unit(r, "m01_stop_enable", m.m01_stop_enable);
  unit(r, "reset", m.reset);
  const auto& search = m.block_search;
  r.flag("block_search.request_r", search.request_r);
  r.integer("block_search.state_r.state", search.state_r.state);
  r.flag("block_search.state_r.continuation_moved", search.state_r.continuation_moved);
  r.integer("block_search.state_r.continuation_block_nr", search.state_r.continuation_block_nr);
  r.integer("block_search.state_r.continuation_nc_line", search.state_r.continuation_nc_line);
  r.number("block_search.state_r.continuation_distance_m", search.state_r.continuation_distance * hli_unit_m);
  r.flag("program_block_ignore.request_r", m.program_block_ignore.request_r);
  r.integer("program_block_ignore.state_r", m.program_block_ignore.state_r);
}

void columns(Row& r, const hil::hli_control_t& m) {
  head(r, m);
  unit(r, "program_start", m.program_start);
  unit(r, "feedhold", m.feedhold);
  r.number("override.command_w_ratio", m.override.command_w * override_unit);
  r.flag("override.enable_w", m.override.enable_w);
  unit(r, "delete_distance_to_go", m.delete_distance_to_go);
  r.integer("delete_distance_to_go_activation.command_w", m.delete_distance_to_go_activation.command_w);
  r.flag("delete_distance_to_go_activation.enable_w", m.delete_distance_to_go_activation.enable_w);
  unit(r, "m_function_ack", m.m_function_ack);
  unit(r, "h_function_ack", m.h_function_ack);
  unit(r, "s_function_ack", m.s_function_ack);
  unit(r, "t_function_ack", m.t_function_ack);
  unit(r, "backward_motion", m.backward_motion);
  const auto& insert = m.insert_cmd;
  r.number("insert_cmd.command_w.dist_or_pos_m", insert.command_w.dist_or_pos * hli_unit_m);
  r.integer("insert_cmd.command_w.rel_abs_mode", insert.command_w.rel_abs_mode);
  r.integer("insert_cmd.command_w.axis_nr", insert.command_w.axis_nr);
  r.integer("insert_cmd.command_w.m_function_nr", insert.command_w.m_function_nr);
  r.integer("insert_cmd.command_w.add_nr", insert.command_w.add_nr);
  r.flag("insert_cmd.enable_w", insert.enable_w);
  r.flag("insert_cmd.semaphor_rw", insert.semaphor_rw);
  unit(r, "continue_motion", m.continue_motion);
  unit(r, "m01_stop_enable", m.m01_stop_enable);
  unit(r, "reset", m.reset);
  const auto& search = m.block_search;
  r.integer("block_search.command_w.type", search.command_w.type);
  r.integer("block_search.command_w.block_nr", search.command_w.block_nr);
  r.number("block_search.command_w.distance_m", search.command_w.distance * hli_unit_m);
  r.flag("block_search.enable_w", search.enable_w);
  r.integer("program_block_ignore.command_w", m.program_block_ignore.command_w);
  r.flag("program_block_ignore.enable_w", m.program_block_ignore.enable_w);
  r.integer("zero_offset.command_w.group", m.zero_offset.command_w.group);
  r.integer("zero_offset.command_w.axis_nr", m.zero_offset.command_w.axis_nr);
  r.number("zero_offset.command_w.value_m", m.zero_offset.command_w.value * hli_unit_m);
  r.flag("zero_offset.enable_w", m.zero_offset.enable_w);
}

void columns(Row& r, const hil::participant_t& m) {
  head(r, m);
  r.text("name", m.name);
  r.integer("phase", m.phase);
  r.integer("verdicts", m.verdicts);
  r.integer("n_rejected", m.n_rejected);
  traffic(r, m.rejected);
  r.integer("n_lost", m.n_lost);
  for (size_t i = 0; i < m.lost.size(); ++i) r.text(at("lost", i), m.lost[i]);
  for (size_t i = 0; i < m.lost_cycle.size(); ++i) r.integer(at("lost_cycle", i), m.lost_cycle[i]);
}

void columns(Row& r, const hil::rt_stats_t& m) {
  head(r, m);
  r.flag("is_final", m.is_final);
  r.number("cycle_time_s", m.cycle_us * 1e-6);
  r.text("scheduling", m.scheduling);
  r.integer("ticks", m.ticks);
  r.integer("overruns", m.overruns);
  r.number("jitter_p50_s", m.jitter_p50_us * 1e-6);
  r.number("jitter_p99_s", m.jitter_p99_us * 1e-6);
  r.number("jitter_max_s", m.jitter_max_us * 1e-6);
  r.integer("n_participants", m.n_participants);
  const std::pair<const char*, const std::vector<int64_t>*> counts[] = {
      {"in_time", &m.in_time},           {"late", &m.late},           {"missing", &m.missing},
      {"out_of_order", &m.out_of_order}, {"duplicate", &m.duplicate}, {"longest_gap_cycles", &m.longest_gap_cycles},
      {"watchdog_cycles", &m.watchdog_cycles}};
  for (size_t i = 0; i < m.name.size(); ++i) {
    r.text(at("name", i), m.name[i]);
    for (const auto& [name, values] : counts)
      if (i < values->size()) r.integer(at(name, i), (*values)[i]);
  }
}

void columns(Row& r, const hil::run_manifest_t& m) {
  head(r, m);
  r.text("rig_version", m.rig_version);
  r.text("scenario_name", m.scenario_name);
  r.number("cycle_time_s", m.cycle_us * 1e-6);
  r.number("answer_timeout_s", m.answer_timeout_ms * 1e-3);
  r.integer("scenario_bytes", m.scenario_bytes);
  r.integer("scenario_digest", m.scenario_digest);
  r.integer("n_participants", m.n_participants);
  for (size_t i = 0; i < m.participants.size(); ++i) r.text(at("participants", i), m.participants[i]);
}

void columns(Row& r, const hil::scenario_text_t& m) {
  head(r, m);
  r.integer("digest", m.digest);
  r.text("yaml", m.yaml);
  r.text("nc_program", m.nc_program);
}

void columns(Row& r, const hil::log_summary_t& m) {
  head(r, m);
  r.integer("recorded", m.recorded);
  r.integer("socket_drops", m.socket_drops);
  r.integer("n_missing", m.n_missing);
  for (size_t i = 0; i < m.missing.size(); ++i) r.text(at("missing", i), m.missing[i]);
  r.integer("n_rejected", m.n_rejected);
  traffic(r, m.rejected);
}

// A message type of the rig, known by the fingerprint its bytes begin with.
struct Kind {
  const char* type;
  int64_t hash;
  // Its cycle is the simulated time it belongs to (the lock-step messages,
  // events, statistics); the others (handshake, manifest, the logger's own
  // records) follow the wall clock.
  bool simulated_time;
  bool (*columns)(const LogRecord& e, Row& row);  // false: not decodable as this type
};

template <typename Message>
Kind kind(const char* type, bool simulated_time) {
  return {type, Message::getHash(), simulated_time, [](const LogRecord& e, Row& row) {
            Message m{};  // decode fills it; {} quiets GCC, which cannot see that
            if (!lcm_support::decode_untrusted(e.data.data(), e.data.size(), m)) return false;
            columns(row, m);
            return true;
          }};
}

const std::vector<Kind>& kinds() {
  static const std::vector<Kind> all = {
      kind<hil::axis_setpoint_t>("axis_setpoint_t", true), kind<hil::axis_state_t>("axis_state_t", true),
      kind<hil::hli_state_t>("hli_state_t", true),         kind<hil::hli_control_t>("hli_control_t", true),
      kind<hil::event_t>("event_t", true),                 kind<hil::rt_stats_t>("rt_stats_t", true),
      kind<hil::participant_t>("participant_t", false),    kind<hil::run_manifest_t>("run_manifest_t", false),
      kind<hil::scenario_text_t>("scenario_text_t", false), kind<hil::log_summary_t>("log_summary_t", false)};
  return all;
}

std::optional<int64_t> fingerprint(const LogRecord& e) {
  if (e.data.size() < 8) return std::nullopt;
  const uint8_t* b = e.data.data();
  uint64_t h = 0;
  for (int i = 0; i < 8; ++i) h = h << 8 | b[i];  // LCM encodes it big-endian
  return static_cast<int64_t>(h);
}

const Kind* kind_of(const LogRecord& e) {
  const std::optional<int64_t> hash = fingerprint(e);
  for (const Kind& k : kinds())
    if (hash && *hash == k.hash) return &k;
  return nullptr;
}

// A channel's columns: every column any of its messages has, in their order
// (arrays of different lengths, one message to the next).
struct Header {
  std::vector<std::string> names;
  std::unordered_map<std::string, size_t> position;
  std::vector<std::string> last;  // the last row's names: most rows repeat them

  // A name the header lacks goes right after the row's name before it (the
  // front if none). One merge per row that brings new names, not an insert
  // each: a row may bring thousands (a crafted array length).
  void add(const std::vector<std::string>& row) {
    if (row == last) return;
    last = row;
    std::unordered_map<size_t, std::vector<const std::string*>> after;  // header index + 1 -> new names
    size_t anchor = 0;
    for (const std::string& name : row) {
      if (const auto p = position.find(name); p != position.end()) anchor = p->second + 1;
      else if (position.emplace(name, 0).second) after[anchor].push_back(&name);
    }
    if (after.empty()) return;
    std::vector<std::string> merged;
    for (size_t i = 0; i <= names.size(); ++i) {
      if (const auto a = after.find(i); a != after.end())
        for (const std::string* name : a->second) merged.push_back(*name);
      if (i < names.size()) merged.push_back(std::move(names[i]));
    }
    names = std::move(merged);
    for (size_t i = 0; i < names.size(); ++i) position[names[i]] = i;
  }
};

// No rig message has a tenth as many columns (hli_state_t: 4 per axis);
// a row with more (an array length a crafted log sets to 32767) is left out,
// else every row of its channel would carry its empty cells.
constexpr size_t max_columns = 1024;
// Files open at once, one per channel: below the usual limit of 1024
// descriptors. A rig log has a dozen channels.
constexpr size_t max_channels = 500;

struct ChannelPass {
  const Kind* kind = nullptr;
  size_t index = 0;  // in CsvExport::channels, if exported
  int64_t messages = 0;
  Header header;
  std::unique_ptr<std::ofstream> out;
};

// The channel's name as a file name; another channel's file already named
// so (channels that differ only in characters a file name cannot hold):
// "_2", "_3" appended. At most 200 characters of it: a channel name may have
// 999 (LCM's limit), a file name 255.
std::string file_name(const std::string& channel, std::set<std::string>& taken) {
  std::string name;
  for (const char c : channel.substr(0, 200))
    name += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_';
  if (name.empty()) name = "_";
  std::string file = name + ".csv";
  for (int n = 2; !taken.insert(file).second; ++n) file = name + "_" + std::to_string(n) + ".csv";
  return file;
}

// Seconds from `start_us` to `us`: timestamps are the log's, any int64.
std::string seconds_since(int64_t start_us, int64_t us) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6f", (static_cast<double>(us) - static_cast<double>(start_us)) * 1e-6);
  return buf;
}

}  // namespace

std::optional<MessageColumns> message_columns(const LogRecord& record) {
  const Kind* k = kind_of(record);
  Row row(false);
  if (!k || !k->columns(record, row)) return std::nullopt;
  return MessageColumns{k->type, k->simulated_time, row.cycle, row.names(), row.cells(), row.kinds()};
}

std::string csv_quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + '"';
}

CsvExport export_csv(const std::string& log_path, const std::string& dir) {
  CsvExport result;
  std::map<std::string, ChannelPass> channels;
  std::vector<std::string> order;  // of the channels' first messages
  std::optional<int64_t> start_us;

  // First pass: each channel's type and columns, the cycle time.
  {
    EventLogReader file(log_path);
    while (const LogRecord* e = file.next()) {
      ++result.messages;
      if (!start_us) start_us = e->timestamp;
      auto [entry, first] = channels.try_emplace(e->channel);
      ChannelPass& c = entry->second;
      if (first) order.push_back(e->channel);
      ++c.messages;
      const Kind* k = kind_of(*e);
      if (!k || (c.kind && c.kind != k)) continue;
      Row row(true);
      if (!k->columns(*e, row)) continue;
      c.kind = k;
      if (row.names().size() <= max_columns) c.header.add(row.names());
      if (!result.cycle_s && k->hash == hil::run_manifest_t::getHash()) {
        hil::run_manifest_t m{};
        if (lcm_support::decode_untrusted(e->data.data(), e->data.size(), m) && m.cycle_us > 0)
          result.cycle_s = m.cycle_us * 1e-6;
      }
    }
    result.damage = file.damage().describe();
  }
  if (result.messages == 0) throw std::runtime_error(log_path + " is not an LCM event log (no event found)");

  fs::create_directories(dir);
  std::set<std::string> files;
  for (const std::string& channel : order) {
    ChannelPass& c = channels[channel];
    if (!c.kind) {
      result.unknown.emplace_back(channel, c.messages);
      continue;
    }
    if (result.channels.size() == max_channels) {
      c.kind = nullptr;  // not written in the second pass
      result.too_many.emplace_back(channel, c.messages);
      continue;
    }
    CsvChannel out;
    out.channel = channel;
    out.type = c.kind->type;
    out.file = (fs::path(dir) / file_name(channel, files)).string();
    out.simulated_time = c.kind->simulated_time && result.cycle_s;
    c.out = std::make_unique<std::ofstream>(out.file);
    if (!*c.out) throw std::runtime_error("cannot write " + out.file);
    *c.out << (out.simulated_time ? "t_s,log_t_s" : "log_t_s");
    for (const std::string& name : c.header.names) *c.out << ',' << name;
    *c.out << '\n';
    c.index = result.channels.size();
    result.channels.push_back(out);
  }

  // Second pass: the rows, each cell under its column, empty where a
  // message lacks it.
  EventLogReader file(log_path);
  std::string line;
  while (const LogRecord* e = file.next()) {
    ChannelPass& c = channels[e->channel];
    if (!c.kind) continue;
    CsvChannel& out = result.channels[c.index];
    Row row(false);
    if (kind_of(*e) != c.kind || !c.kind->columns(*e, row)) {
      ++out.skipped;
      continue;
    }
    if (row.names().size() > max_columns) {
      ++out.too_wide;
      continue;
    }
    line.clear();
    if (out.simulated_time) {
      char t[32];
      std::snprintf(t, sizeof t, "%.15g,", static_cast<double>(row.cycle) * *result.cycle_s);
      line += t;
    }
    line += seconds_since(*start_us, e->timestamp);
    size_t k = 0;
    for (const std::string& name : c.header.names) {
      line += ',';
      if (k < row.names().size() && row.names()[k] == name) line += row.cells()[k++];
    }
    *c.out << line << '\n';
    ++out.rows;
  }
  for (auto& entry : channels)
    if (entry.second.out && !entry.second.out->flush())
      throw std::runtime_error("cannot write " + result.channels[entry.second.index].file);
  return result;
}

}  // namespace hil::logger
