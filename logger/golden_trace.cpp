#include "golden_trace.hpp"

#include <lzma.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "channels.hpp"
#include "event_log_reader.hpp"
#include "run_identity.hpp"

namespace hil::logger {
namespace {

constexpr const char* magic_line = "hil golden trace 1";
constexpr int64_t largest_quantized = 100'000'000'000'000'000;  // 1e17: a 4th-order extrapolation still fits int64

bool kept(const std::string& channel) {
  return channel == channels::hli_state || channel == channels::event ||
         channels::names_an_axis(channel, "_CMD");
}

std::string unquoted(const std::string& cell) {
  std::string out;
  for (size_t i = 1; i + 1 < cell.size(); ++i) {
    out += cell[i];
    if (cell[i] == '"') ++i;  // a doubled quote
  }
  return out;
}

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\') out += "\\\\";
    else if (c == '\t') out += "\\t";
    else if (c == '\n') out += "\\n";
    else out += c;
  }
  return out;
}

std::string unescaped(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\' || i + 1 == text.size()) {
      out += text[i];
      continue;
    }
    const char c = text[++i];
    out += c == 't' ? '\t' : c == 'n' ? '\n' : c;
  }
  return out;
}

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> out(1);
  for (const char c : line) {
    if (c == '\t') out.emplace_back();
    else out.back() += c;
  }
  return out;
}

std::string number_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The step a number column is kept in, SI: a length's 1e-10 mm; a
// velocity's and an acceleration's what that step is over one and two
// cycles of 1 ms, so that each field is kept as finely as the position it
// moves the axis by in a cycle.
double quantum_of(const std::string& column) {
  if (ends_with(column, "_m_s2") || ends_with(column, "_rad_s2")) return 1e-7;
  if (ends_with(column, "_m_s") || ends_with(column, "_rad_s")) return 1e-10;
  return 1e-13;
}

// A column's last values, in quanta: what the next one is predicted from.
// Numbers by the polynomial through the last 1 .. 4 that predicted the
// latest one best (a jerk-limited motion's positions are cubics, a curve's
// velocities smooth; a step is followed by a hold): the decoder makes the
// same choice from the same values. Integers by the last one.
struct ColumnHistory {
  int64_t h[4] = {0, 0, 0, 0};  // h[0] the latest
  int known = 0;
  int order = 0;  // the extrapolation that predicts the next value
  static int64_t extrapolated(const int64_t* h, int order) {
    switch (order) {
      case 0: return h[0];
      case 1: return 2 * h[0] - h[1];
      case 2: return 3 * h[0] - 3 * h[1] + h[2];
      default: return 4 * h[0] - 6 * h[1] + 4 * h[2] - h[3];
    }
  }
  int64_t predicted(CellKind kind) const {
    if (!known) return 0;
    return kind == CellKind::number ? extrapolated(h, std::min(order, known - 1)) : h[0];
  }
  void push(int64_t v) {
    // The order that would have predicted v best from what was known before it.
    int64_t best = -1;
    for (int o = 0; o < std::min(known, 4); ++o) {
      const int64_t miss = v - extrapolated(h, o);
      const int64_t size = miss < 0 ? -miss : miss;
      if (best < 0 || size < best) best = size, order = o;
    }
    h[3] = h[2];
    h[2] = h[1];
    h[1] = h[0];
    h[0] = v;
    known = std::min(known + 1, 4);
  }
};

bool quantizable(double v, double quantum, int64_t* q) {
  if (!std::isfinite(v) || std::fabs(v) / quantum > static_cast<double>(largest_quantized)) return false;
  *q = std::llround(v / quantum);
  return true;
}

std::string xz(const std::string& text) {
  std::string out(lzma_stream_buffer_bound(text.size()), '\0');
  size_t used = 0;
  const lzma_ret r = lzma_easy_buffer_encode(6, LZMA_CHECK_CRC64, nullptr, reinterpret_cast<const uint8_t*>(text.data()),
                                             text.size(), reinterpret_cast<uint8_t*>(out.data()), &used, out.size());
  if (r != LZMA_OK) throw std::runtime_error("xz compression failed (" + std::to_string(r) + ")");
  out.resize(used);
  return out;
}

std::string unxz(const std::string& packed, const std::string& path) {
  lzma_stream s = LZMA_STREAM_INIT;
  if (lzma_stream_decoder(&s, UINT64_MAX, 0) != LZMA_OK) throw std::runtime_error("xz decoder failed to start");
  std::string out;
  uint8_t buf[1 << 16];
  s.next_in = reinterpret_cast<const uint8_t*>(packed.data());
  s.avail_in = packed.size();
  lzma_ret r = LZMA_OK;
  while (r == LZMA_OK) {
    s.next_out = buf;
    s.avail_out = sizeof buf;
    r = lzma_code(&s, LZMA_FINISH);
    out.append(reinterpret_cast<char*>(buf), sizeof buf - s.avail_out);
  }
  lzma_end(&s);
  if (r != LZMA_STREAM_END) throw std::runtime_error(path + ": not a whole xz stream (" + std::to_string(r) + ")");
  return out;
}

std::string cell_text(const TraceCell& c) {
  switch (c.kind) {
    case CellKind::number: {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.15g", c.number);
      return buf;
    }
    case CellKind::integer: return std::to_string(c.integer);
    case CellKind::text: return "'" + c.text + "'";
  }
  return "";
}

bool agree(const TraceCell& a, const TraceCell& b, const std::string& column) {
  if (a.kind != b.kind) return false;
  switch (a.kind) {
    case CellKind::number:
      if (std::isnan(a.number) || std::isnan(b.number)) return std::isnan(a.number) && std::isnan(b.number);
      if (std::isinf(a.number) || std::isinf(b.number)) return a.number == b.number;
      return std::fabs(a.number - b.number) <= golden_tolerance_of(column, std::max(std::fabs(a.number), std::fabs(b.number)));
    case CellKind::integer: return a.integer == b.integer;
    case CellKind::text: return a.text == b.text;
  }
  return false;
}

}  // namespace

double golden_tolerance_of(const std::string& column, double magnitude) {
  return std::max(10 * quantum_of(column), 1e-12 * magnitude);
}

TraceChannel& GoldenTrace::channel(const std::string& name, const std::string& type) {
  for (TraceChannel& c : channels_)
    if (c.name == name) return c;
  channels_.push_back({name, type, {}});
  return channels_.back();
}

void GoldenTrace::add(const LogRecord& record) {
  if (!kept(record.channel)) return;
  const std::optional<MessageColumns> m = message_columns(record);
  if (!m) return;
  TraceChannel& c = channel(record.channel, m->type);
  TraceRow row;
  row.cycle = m->cycle;
  std::vector<std::string> names;
  for (size_t k = 0; k < m->cells.size(); ++k) {
    if (m->names[k] == "run_id") continue;  // differs from run to run
    TraceCell cell;
    cell.kind = m->kinds[k];
    if (cell.kind == CellKind::number) cell.number = std::strtod(m->cells[k].c_str(), nullptr);
    else if (cell.kind == CellKind::integer) cell.integer = std::stoll(m->cells[k]);
    else cell.text = unquoted(m->cells[k]);
    names.push_back(m->names[k]);
    row.cells.push_back(std::move(cell));
  }
  row.names = !c.rows.empty() && *c.rows.back().names == names
                  ? c.rows.back().names
                  : std::make_shared<const std::vector<std::string>>(std::move(names));
  c.rows.push_back(std::move(row));
}

void GoldenTrace::finish() {
  for (TraceChannel& c : channels_) {
    if (c.name != channels::event) continue;
    std::stable_sort(c.rows.begin(), c.rows.end(), [](const TraceRow& a, const TraceRow& b) {
      if (a.cycle != b.cycle) return a.cycle < b.cycle;
      for (size_t k = 0; k < std::min(a.cells.size(), b.cells.size()); ++k) {
        const std::string ta = cell_text(a.cells[k]), tb = cell_text(b.cells[k]);
        if (ta != tb) return ta < tb;
      }
      return a.cells.size() < b.cells.size();
    });
  }
}

std::string GoldenTrace::text() const {
  std::ostringstream out;
  out << magic_line << '\n' << "# " << escaped(comment) << '\n';
  for (const TraceChannel& c : channels_) {
    out << '@' << c.name << '\t' << c.type << '\n';
    const std::vector<std::string>* names = nullptr;
    std::vector<ColumnHistory> history;
    std::vector<std::string> last_text;
    for (const TraceRow& row : c.rows) {
      // Rows share their names (add(), parse()): compared only where they do not.
      const bool same_names = names == row.names.get() || (names && *names == *row.names);
      names = row.names.get();
      if (!same_names) {  // a header starts the columns' histories anew
        out << '=';
        for (size_t k = 0; k < names->size(); ++k)
          out << (k ? "\t" : "") << static_cast<char>(row.cells[k].kind) << ':' << (*names)[k];
        out << '\n';
        history.assign(names->size(), {});
        last_text.assign(names->size(), "");
      }
      for (size_t k = 0; k < row.cells.size(); ++k) {
        if (k) out << '\t';
        const TraceCell& cell = row.cells[k];
        int64_t q = 0;
        if (cell.kind == CellKind::text) {
          if (history[k].known == 0 || cell.text != last_text[k]) out << '\'' << escaped(cell.text);
          last_text[k] = cell.text;
          history[k].known = 1;
        } else if (cell.kind == CellKind::integer || quantizable(cell.number, quantum_of((*names)[k]), &q)) {
          if (cell.kind == CellKind::integer) q = cell.integer;
          const int64_t residual = q - history[k].predicted(cell.kind);
          if (residual != 0) out << residual;
          history[k].push(q);
        } else {
          out << '~' << number_text(cell.number);
          history[k] = {};
        }
      }
      out << '\n';
    }
  }
  return out.str();
}

GoldenTrace GoldenTrace::parse(const std::string& text, const std::string& source) {
  GoldenTrace trace;
  std::istringstream in(text);
  std::string line;
  int64_t line_nr = 0;
  auto fail = [&](const std::string& why) -> void {
    throw std::runtime_error(source + ":" + std::to_string(line_nr) + ": " + why);
  };
  ++line_nr;
  if (!std::getline(in, line) || line != magic_line) fail(std::string("not a golden trace (no '") + magic_line + "')");
  TraceChannel* c = nullptr;
  std::shared_ptr<const std::vector<std::string>> names;
  std::vector<CellKind> kinds;
  std::vector<ColumnHistory> history;
  std::vector<std::string> last_text;
  int cycle_column = -1;
  while (std::getline(in, line)) {
    ++line_nr;
    if (line.rfind("# ", 0) == 0) {
      trace.comment = unescaped(line.substr(2));
      continue;
    }
    if (!line.empty() && line[0] == '@') {
      const std::vector<std::string> f = split_tabs(line.substr(1));
      if (f.size() != 2) fail("a channel line is '@NAME<TAB>TYPE'");
      c = &trace.channel(f[0], f[1]);
      names.reset();
      continue;
    }
    if (!c) fail("a row before the first channel line");
    if (!line.empty() && line[0] == '=') {
      std::vector<std::string> columns;
      kinds.clear();
      cycle_column = -1;
      for (const std::string& column : split_tabs(line.substr(1))) {
        if (column.size() < 3 || column[1] != ':' || std::string("nit").find(column[0]) == std::string::npos)
          fail("a column is 'n:NAME', 'i:NAME' or 't:NAME', not '" + column + "'");
        kinds.push_back(static_cast<CellKind>(column[0]));
        columns.push_back(column.substr(2));
        if (columns.back() == "cycle" && kinds.back() == CellKind::integer)
          cycle_column = static_cast<int>(columns.size()) - 1;
      }
      history.assign(columns.size(), {});
      last_text.assign(columns.size(), "");
      names = std::make_shared<const std::vector<std::string>>(std::move(columns));
      continue;
    }
    if (!names) fail("a row before its channel's column line");
    const std::vector<std::string> f = split_tabs(line);
    if (f.size() != names->size())
      fail(std::to_string(f.size()) + " cells where the columns are " + std::to_string(names->size()));
    TraceRow row;
    row.names = names;
    for (size_t k = 0; k < f.size(); ++k) {
      TraceCell cell;
      cell.kind = kinds[k];
      const std::string& s = f[k];
      if (kinds[k] == CellKind::text) {
        if (!s.empty()) last_text[k] = s[0] == '\'' ? unescaped(s.substr(1)) : s;
        cell.text = last_text[k];
      } else if (!s.empty() && s[0] == '~') {
        cell.number = std::strtod(s.c_str() + 1, nullptr);
        history[k] = {};
      } else {
        int64_t residual = 0;
        if (!s.empty()) try {
            size_t used = 0;
            residual = std::stoll(s, &used);
            if (used != s.size()) throw std::invalid_argument(s);
          } catch (const std::exception&) {
            fail("'" + s + "' is no whole number");
          }
        const int64_t q = history[k].predicted(kinds[k]) + residual;
        history[k].push(q);
        if (kinds[k] == CellKind::integer) cell.integer = q;
        else cell.number = static_cast<double>(q) * quantum_of((*names)[k]);
      }
      row.cells.push_back(std::move(cell));
    }
    if (cycle_column >= 0) row.cycle = row.cells[static_cast<size_t>(cycle_column)].integer;
    c->rows.push_back(std::move(row));
  }
  return trace;
}

void GoldenTrace::write(const std::string& path) const {
  const std::string packed = xz(text());
  std::ofstream out(path, std::ios::binary);
  out.write(packed.data(), static_cast<std::streamsize>(packed.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

GoldenTrace GoldenTrace::read(const std::string& path) { return parse(unxz(read_text(path), path), path); }

bool is_golden_trace_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[6] = {};
  in.read(head, sizeof head);
  return in && std::string(head, sizeof head) == std::string("\xFD" "7zXZ\0", 6);
}

GoldenTrace golden_trace_of_log(const std::string& path) {
  GoldenTrace trace;
  EventLogReader file(path);
  while (const LogRecord* e = file.next()) trace.add(*e);
  if (file.records() == 0) throw std::runtime_error(path + " is not an LCM event log (no event found)");
  if (file.damage().any()) throw std::runtime_error(path + " is damaged: " + file.damage().describe());
  trace.finish();
  return trace;
}

TraceComparison compare_golden_traces(const GoldenTrace& golden, const GoldenTrace& now, size_t max_listed) {
  TraceComparison result;
  auto differ = [&](const std::string& what) {
    if (result.differences.size() < max_listed) result.differences.push_back(what);
    ++result.count;
  };
  std::map<std::string, const TraceChannel*> in_now;
  for (const TraceChannel& c : now.channels()) in_now[c.name] = &c;
  for (const TraceChannel& g : golden.channels()) {
    const auto found = in_now.find(g.name);
    if (found == in_now.end()) {
      differ(g.name + ": " + std::to_string(g.rows.size()) + " message(s) in the golden trace, none now");
      continue;
    }
    const TraceChannel& n = *found->second;
    in_now.erase(found);
    const size_t common = std::min(g.rows.size(), n.rows.size());
    // The last pair of (shared) name lists found equal: rows of a channel share theirs.
    const std::vector<std::string>*same_a = nullptr, *same_b = nullptr;
    for (size_t i = 0; i < common; ++i) {
      const TraceRow& a = g.rows[i];
      const TraceRow& b = n.rows[i];
      const std::string where = g.name + " message " + std::to_string(i) + " cycle " + std::to_string(a.cycle) +
                                (a.cycle != b.cycle ? " (now " + std::to_string(b.cycle) + ")" : "");
      if ((a.names.get() != same_a || b.names.get() != same_b) && *a.names != *b.names) {
        differ(where + ": other fields (" + std::to_string(a.names->size()) + " golden, " +
               std::to_string(b.names->size()) + " now)");
        continue;
      }
      same_a = a.names.get();
      same_b = b.names.get();
      for (size_t k = 0; k < a.cells.size(); ++k)
        if (!agree(a.cells[k], b.cells[k], (*a.names)[k])) {
          std::string off;
          if (a.cells[k].kind == CellKind::number && b.cells[k].kind == CellKind::number) {
            char buf[40];
            std::snprintf(buf, sizeof buf, " (off by %.3g)", b.cells[k].number - a.cells[k].number);
            off = buf;
          }
          differ(where + " " + (*a.names)[k] + ": golden " + cell_text(a.cells[k]) + ", now " +
                 cell_text(b.cells[k]) + off);
        }
    }
    if (g.rows.size() != n.rows.size())
      differ(g.name + ": " + std::to_string(g.rows.size()) + " message(s) golden, " + std::to_string(n.rows.size()) +
             " now");
  }
  for (const auto& [name, c] : in_now)
    differ(name + ": " + std::to_string(c->rows.size()) + " message(s) now, none in the golden trace");
  return result;
}

}  // namespace hil::logger
