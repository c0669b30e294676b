// RIG-4 RIG-9 (issue 33): crafted logs against every reader of a log. Each
// case is one the readers crashed on, took minutes or hundreds of MB for,
// or judged wrongly before; the log fuzz (tests/fuzz/log_fuzz.hpp) found or
// confirms them. The logs are real in-process runs (the fuzz's base logs),
// changed in one place.
#include <catch2/catch.hpp>

#include <hil/hli_state_t.hpp>
#include <hil/participant_t.hpp>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "channels.hpp"
#include "csv_export.hpp"
#include "event_log_reader.hpp"
#include "log_fuzz.hpp"
#include "rerun.hpp"
#include "run_log.hpp"
#include "same_path.hpp"
#include "untrusted_decode.hpp"
#include "verdict.hpp"

using namespace hil;
namespace fs = std::filesystem;

namespace {

const fs::path& work_dir() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("hil_crafted_log_test_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

// The passing run's log (and its records), made once.
const fuzz::BaseLog& passing_run() {
  static const std::vector<fuzz::BaseLog> bases = fuzz::make_base_logs((work_dir() / "base").string());
  return bases.front();
}

std::string write_log(const std::string& name, const std::vector<uint8_t>& bytes) {
  const std::string path = (work_dir() / name).string();
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                              static_cast<std::streamsize>(bytes.size()));
  return path;
}
std::string write_log(const std::string& name, const fuzz::LogRecords& log) { return write_log(name, fuzz::log_bytes(log)); }

void put_be(std::vector<uint8_t>& b, size_t at, uint64_t v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i, v >>= 8) b[at + static_cast<size_t>(i)] = static_cast<uint8_t>(v);
}

size_t cnc_run_end(const fuzz::LogRecords& log) {
  for (size_t i = 0; i < log.records.size(); ++i) {
    hil::participant_t m{};
    const logger::LogRecord& r = log.records[i];
    if (r.channel == channels::participant && lcm_support::decode_untrusted(r.data.data(), r.data.size(), m) &&
        m.name == "cnc" && m.phase == hil::participant_t::PHASE_RUN_END)
      return i;
  }
  FAIL("no cnc RUN_END in the log");
  return 0;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& line : lines) out += line + "\n";
  return out;
}

struct Judged {
  logger::RunVerdict verdict;
  std::string problems;
  double seconds = 0;
};
Judged judge(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<logger::CheckReport> check;
  const logger::RunLog log = logger::read_run_log(path, &check);
  Judged j;
  j.problems = joined(logger::log_problems(log.facts));
  j.verdict = logger::judge_run({{"cnc", 0}}, log.facts, check && check->passed() ? "" : "check failed");
  j.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return j;
}

}  // namespace

TEST_CASE("RIG-9 crafted log: the unchanged run passes (the cases below change one thing)", "[log][crafted]") {
  const Judged j = judge(passing_run().path);
  CHECK(j.problems.empty());
  CHECK(j.verdict.passed);
}

// Before: std::bad_alloc out of the verdict (hil run, hil check: exit 2, no
// report) for 10^12, -1000, 2^63 - 1; 2^32 took 61 s and 536 MB.
TEST_CASE("RIG-9 crafted log: a cnc RUN_END naming an absurd cycle fails the verdict at once, naming it",
          "[log][crafted]") {
  const fuzz::BaseLog& run = passing_run();
  const size_t end = cnc_run_end(run.records);
  const int64_t held = static_cast<int64_t>(std::count_if(run.records.records.begin(), run.records.records.end(),
                                                          [](const auto& r) { return r.channel == channels::hli_state; }));
  for (const int64_t cycle : {int64_t{1000000000000}, int64_t{-1000}, std::numeric_limits<int64_t>::max(),
                              int64_t{1} << 32, std::numeric_limits<int64_t>::min()}) {
    CAPTURE(cycle);
    fuzz::LogRecords forged = run.records;
    put_be(forged.records[end].data, 24, static_cast<uint64_t>(cycle), 8);
    const Judged j = judge(write_log("run_end.lcmlog", forged));
    CHECK_FALSE(j.verdict.passed);
    CHECK_THAT(j.problems, Catch::Contains("the cnc's RUN_END names cycle " + std::to_string(cycle) +
                                           (cycle < 0 ? ", before the first (0)"
                                                      : ", beyond the " + std::to_string(held) + " cycles the log holds")));
    CHECK(j.seconds < 2);
  }
}

TEST_CASE("RIG-9 crafted log: a RUN_END cycle the log could hold is checked cycle by cycle", "[log][crafted]") {
  const fuzz::BaseLog& run = passing_run();
  fuzz::LogRecords forged = run.records;
  const size_t end = cnc_run_end(forged);
  const int64_t real = static_cast<int64_t>(
      [&] { uint64_t v = 0; for (int i = 0; i < 8; ++i) v = v << 8 | forged.records[end].data[24 + i]; return v; }());
  put_be(forged.records[end].data, 24, static_cast<uint64_t>(real + 100), 8);
  const Judged j = judge(write_log("run_end_100.lcmlog", forged));
  CHECK_FALSE(j.verdict.passed);
  CHECK_THAT(j.problems, Catch::Contains("HLI_STATE: 100 of " + std::to_string(real + 101) +
                                         " cycles missing (the first: " + std::to_string(real + 1) + ")"));
  CHECK_THAT(j.problems, Catch::Contains("the cnc's RUN_END names cycle " + std::to_string(real + 100) +
                                         ", the logger's seal cycle " + std::to_string(real)));
}

// The forgery: a second RUN_END, which the seal's count gives away
// even where its cycle is the real one.
TEST_CASE("RIG-9 crafted log: a record added, left out or after the seal does not pass", "[log][crafted]") {
  const fuzz::BaseLog& run = passing_run();
  const size_t end = cnc_run_end(run.records);
  const int64_t records = static_cast<int64_t>(run.records.records.size());
  fuzz::LogRecords added = run.records;
  added.records.insert(added.records.begin() + static_cast<std::ptrdiff_t>(end), run.records.records[end]);
  Judged j = judge(write_log("added.lcmlog", added));
  CHECK_FALSE(j.verdict.passed);
  CHECK_THAT(j.problems, Catch::Contains("the logger's seal counts " + std::to_string(records - 1) +
                                         " message(s) written before it, the log holds " + std::to_string(records)));

  fuzz::LogRecords after = run.records;
  after.records.push_back(run.records.records[end]);
  j = judge(write_log("after.lcmlog", after));
  CHECK_FALSE(j.verdict.passed);
  CHECK_THAT(j.problems, Catch::Contains("1 record(s) after the logger's seal (HIL_LOG_END), which it writes last"));
}

// Before: lcm-gen's decoder copied 2 GB from beyond the buffer, SIGSEGV in
// every reader (and in every node that decodes it off the network).
TEST_CASE("RIG-4 crafted log: a string length of -2^31 is an undecodable message, not a crash", "[log][crafted]") {
  hil::participant_t m{};
  m.name = "cnc";
  m.phase = hil::participant_t::PHASE_RUN_END;
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  hil::participant_t back{};
  REQUIRE(lcm_support::decode_untrusted(bytes.data(), bytes.size(), back));
  for (const uint32_t length : {0x80000000u, 0x80000001u, 0xFFFFFFFFu, 0u, 0x7FFFFFFFu}) {
    CAPTURE(length);
    std::vector<uint8_t> crafted = bytes;
    put_be(crafted, 32, length, 4);  // the name's length (after fingerprint, run_id, utime, cycle)
    CHECK_FALSE(lcm_support::decode_untrusted(crafted.data(), crafted.size(), back));
  }

  const fuzz::BaseLog& run = passing_run();
  fuzz::LogRecords crafted = run.records;
  put_be(crafted.records[cnc_run_end(crafted)].data, 32, 0x80000000u, 4);
  const std::string path = write_log("string_length.lcmlog", crafted);
  const Judged j = judge(path);
  CHECK_FALSE(j.verdict.passed);
  CHECK_THAT(j.problems, Catch::Contains("in the log messages of this run or unreadable: HIL_PARTICIPANT: 1 undecodable"));
  CHECK_THAT(j.problems, Catch::Contains("no RUN_END from the cnc"));
  CHECK(logger::export_csv(path, (work_dir() / "string_length_csv").string()).channels.size() > 0);
  std::ostringstream out;
  CHECK(cnc_node::rerun(path, out) == 0);  // the RUN_END is no input of a rerun; its lost list is unread
}

TEST_CASE("RIG-4 untrusted decode: a real message with 80 00 00 00 in it still decodes", "[log][crafted]") {
  hil::participant_t m{};
  m.cycle = 0x8000;  // its low bytes 80 00, then the name's length 00 00 00 04
  m.name = "cnc";
  m.verdicts = static_cast<int32_t>(0x80000000u);  // -2^31 where no length is
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  hil::participant_t back{};
  REQUIRE(lcm_support::decode_untrusted(bytes.data(), bytes.size(), back));
  CHECK(back.cycle == 0x8000);
  CHECK(back.verdicts == std::numeric_limits<int32_t>::min());
  CHECK(back.name == "cnc");
}

// Before: std::length_error ("vector::_M_default_append") out of every reader.
TEST_CASE("RIG-4 crafted log: a negative array length is an undecodable message", "[log][crafted]") {
  const fuzz::BaseLog& run = passing_run();
  fuzz::LogRecords crafted = run.records;
  size_t hli = 0;
  while (crafted.records[hli].channel != channels::hli_state) ++hli;
  const fuzz::FieldMap fields = fuzz::field_map(crafted.records[hli]);
  REQUIRE(fields.array_lengths.size() == 1);  // n_axes
  put_be(crafted.records[hli].data, static_cast<size_t>(fields.array_lengths[0]), 0xFFFF, 2);
  const std::string path = write_log("array_length.lcmlog", crafted);
  const Judged j = judge(path);
  CHECK_FALSE(j.verdict.passed);
  CHECK_THAT(j.problems, Catch::Contains("HLI_STATE: 1 undecodable"));
  const logger::CsvExport x = logger::export_csv(path, (work_dir() / "array_length_csv").string());
  for (const auto& c : x.channels)
    if (c.channel == channels::hli_state) CHECK(c.skipped == 1);
  std::ostringstream out;
  CHECK(cnc_node::rerun(path, out) == 1);
  CHECK_THAT(out.str(), Catch::Contains("differs"));
}

// An HLI state of 32767 axes (a valid message, 600 kB): before, every HLI
// row of the CSV got its 131,000 empty cells (and the header took minutes
// to build, an insert per column).
TEST_CASE("RIG-4 export: a message with more columns than any rig message is left out, counted", "[log][crafted]") {
  const fuzz::BaseLog& run = passing_run();
  fuzz::LogRecords crafted = run.records;
  size_t hli = 0;
  while (crafted.records[hli].channel != channels::hli_state) ++hli;
  hil::hli_state_t wide{};
  REQUIRE(lcm_support::decode_untrusted(crafted.records[hli].data.data(), crafted.records[hli].data.size(), wide));
  wide.n_axes = 32767;
  wide.axis_name.assign(32767, "X");
  wide.axis_position_r.assign(32767, 0);
  wide.lift_active.assign(32767, false);
  wide.lift_suppressed.assign(32767, false);
  std::vector<uint8_t> bytes(static_cast<size_t>(wide.getEncodedSize()));
  wide.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  crafted.records[hli].data = bytes;
  const std::string path = write_log("wide.lcmlog", crafted);
  const auto start = std::chrono::steady_clock::now();
  const logger::CsvExport x = logger::export_csv(path, (work_dir() / "wide_csv").string());
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 10);
  bool found = false;
  for (const auto& c : x.channels)
    if (c.channel == channels::hli_state) {
      found = true;
      CHECK(c.too_wide == 1);
      CHECK(fs::file_size(c.file) < 4 * fs::file_size(run.path));
    }
  CHECK(found);
}

// Before: LCM's reader (datalen + 1 overflows, calloc fails, fread writes
// through NULL) died of SIGSEGV; a cut or damaged record ended the log
// silently, and the verdict judged what was read.
TEST_CASE("RIG-4 event log reader: lengths beyond the file, cut records, garbage are damage, named", "[log][crafted]") {
  const fuzz::BaseLog& run = passing_run();
  const std::vector<uint8_t> whole = fuzz::log_bytes(run.records);
  const size_t second = 28 + run.records.records[0].channel.size() + run.records.records[0].data.size();

  std::vector<uint8_t> huge = whole;
  put_be(huge, second + 24, 0x7FFFFFFF, 4);  // the second record's data length
  logger::EventLogReader reader(write_log("huge.lcmlog", huge));
  int64_t records = 0;
  while (reader.next()) ++records;
  CHECK(records == static_cast<int64_t>(run.records.records.size()) - 1);
  CHECK_THAT(reader.damage().describe(), Catch::Contains("at byte " + std::to_string(second)) &&
                                             Catch::Contains("a record claims"));
  Judged j = judge(write_log("huge.lcmlog", huge));
  CHECK_FALSE(j.verdict.passed);
  CHECK_THAT(j.problems, Catch::Contains("the file is damaged: "));

  std::vector<uint8_t> cut(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(whole.size() / 2));
  j = judge(write_log("cut.lcmlog", cut));
  CHECK_FALSE(j.verdict.passed);
  CHECK_THAT(j.problems, Catch::Contains("the logger did not close the log"));

  std::vector<uint8_t> garbage = whole;
  garbage.insert(garbage.begin() + static_cast<std::ptrdiff_t>(second), {1, 2, 3, 4, 5});
  j = judge(write_log("garbage.lcmlog", garbage));
  CHECK_FALSE(j.verdict.passed);
  CHECK_THAT(j.problems, Catch::Contains("5 byte(s) in 1 place(s) are no LCM event, the first at byte " +
                                         std::to_string(second)));
  CHECK_THAT(logger::compare_run_logs(run.path, write_log("garbage.lcmlog", garbage)), Catch::Contains("is damaged"));
  std::ostringstream out;
  CHECK_THROWS_WITH(cnc_node::rerun(write_log("garbage.lcmlog", garbage), out), Catch::Contains("is damaged"));
}

TEST_CASE("RIG-4 crafted log: 0 bytes and a file that is no log", "[log][crafted]") {
  const std::string empty = write_log("empty.lcmlog", std::vector<uint8_t>{});
  const Judged j = judge(empty);
  CHECK_FALSE(j.verdict.passed);
  CHECK_THAT(j.problems, Catch::Contains("no manifest of the run"));
  const std::string text = (work_dir() / "notes.txt").string();
  std::ofstream(text) << "not an LCM event log\n";
  CHECK_THROWS_WITH(logger::read_run_log(text), Catch::Contains("is not an LCM event log"));
  CHECK_THROWS_WITH(logger::compare_run_logs(text, text), Catch::Contains("is not an LCM event log"));
  CHECK_THROWS_WITH(logger::export_csv(text, (work_dir() / "notes_csv").string()), Catch::Contains("is not an LCM event log"));
}

// Before: a node's RUN_END replaced the ledger under its name; one named
// "log" replaced what reading the log had refused.
TEST_CASE("RIG-9 crafted log: a RUN_END cannot take back what the log refused", "[log][crafted]") {
  const fuzz::BaseLog& run = passing_run();
  fuzz::LogRecords crafted = run.records;
  const size_t end = cnc_run_end(crafted);
  logger::LogRecord junk = crafted.records[end];
  junk.channel = channels::hli_state;  // participant_t bytes: undecodable there
  hil::participant_t as_log{};
  REQUIRE(lcm_support::decode_untrusted(crafted.records[end].data.data(), crafted.records[end].data.size(), as_log));
  as_log.name = "log";
  hil::traffic_count_t harmless{};
  harmless.channel = channels::hli_control;
  harmless.foreign_run = 1;
  as_log.rejected = {harmless};
  as_log.n_rejected = 1;
  logger::LogRecord forged = crafted.records[end];
  forged.data.assign(static_cast<size_t>(as_log.getEncodedSize()), 0);
  as_log.encode(forged.data.data(), 0, static_cast<int>(forged.data.size()));
  crafted.records.insert(crafted.records.begin() + static_cast<std::ptrdiff_t>(end), junk);
  crafted.records.insert(crafted.records.begin() + static_cast<std::ptrdiff_t>(end) + 1, forged);
  const Judged j = judge(write_log("as_log.lcmlog", crafted));
  CHECK_FALSE(j.verdict.passed);
  CHECK_THAT(j.problems, Catch::Contains("HLI_STATE: 1 undecodable"));
}

TEST_CASE("RIG-5 same path: positions that are not numbers never hold", "[log][crafted]") {
  logger::PathTrace reference;
  reference.axes = {"X"};
  reference.modulo_range = {0};
  reference.position = {{0, 1, 2, 3}};
  reference.dist_mm = {0, 1, 2, 3};
  reference.cycle = {0, 1, 2, 3};
  logger::PathTrace variant = reference;
  variant.position[0] = {0, std::nan(""), std::nan(""), std::nan("")};
  logger::SamePathResult r = logger::compare_same_path(reference, variant, 0, 1e-6);
  CHECK_FALSE(r.holds);
  CHECK(r.not_finite == 3);
  variant = reference;
  variant.dist_mm = {0, std::nan(""), 2, 3};
  r = logger::compare_same_path(reference, variant, 0, 1e-6);
  CHECK_FALSE(r.holds);
}
