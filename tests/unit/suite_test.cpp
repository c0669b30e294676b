// RIG-5, RIG-9: what a suite runs (files, folders, shards) and how it
// reports (summaries, JUnit escaping), without running the rig.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "config_error.hpp"
#include "run_summary.hpp"
#include "scenario_files.hpp"
#include "suite_results.hpp"
#include "suite_run.hpp"

namespace fs = std::filesystem;
using namespace hil::rig;

namespace {

fs::path fresh_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hil_suite_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void touch(const fs::path& p) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << "name: x\n";
}

}  // namespace

TEST_CASE("RIG-9 shard: K/N parsed, anything else refused", "[suite]") {
  const Shard s = parse_shard("2/4");
  CHECK(s.index == 2);
  CHECK(s.count == 4);
  for (const char* bad : {"0/4", "5/4", "2", "2/0", "a/b", "1/2/3", " 1/2", "-1/2"})
    CHECK_THROWS_AS(parse_shard(bad), hil::ConfigError);
}

TEST_CASE("RIG-9 shards are disjoint, cover the suite, nearly equal and fixed", "[suite]") {
  std::vector<std::string> files;
  for (int i = 0; i < 23; ++i) files.push_back("f" + std::to_string(100 + i));
  for (int n = 1; n <= 30; ++n) {
    std::vector<std::string> all;
    size_t smallest = files.size(), largest = 0;
    for (int k = 1; k <= n; ++k) {
      const auto slice = shard_of(files, {k, n});
      CHECK(slice == shard_of(files, {k, n}));
      smallest = std::min(smallest, slice.size());
      largest = std::max(largest, slice.size());
      all.insert(all.end(), slice.begin(), slice.end());
    }
    std::sort(all.begin(), all.end());
    CHECK(all == files);
    CHECK(largest - smallest <= 1);
  }
  CHECK(shard_of(files, {1, 4}).front() == "f100");
  CHECK(shard_of(files, {2, 4}).front() == "f101");
}

TEST_CASE("RIG-5 suite files: folders recursively in path order, each file once", "[suite]") {
  const fs::path dir = fresh_folder("collect");
  touch(dir / "b.yaml");
  touch(dir / "a" / "z.yaml");
  touch(dir / "a" / "y.yml");
  touch(dir / "a-b" / "x.yaml");
  touch(dir / "notes.txt");
  const std::string d = dir.string();
  const auto files = collect_scenario_files({d, d + "/b.yaml"});
  REQUIRE(files.size() == 4);
  CHECK(files[0] == d + "/a/y.yml");
  CHECK(files[1] == d + "/a/z.yaml");
  CHECK(files[2] == d + "/a-b/x.yaml");
  CHECK(files[3] == d + "/b.yaml");
  CHECK_THROWS_AS(collect_scenario_files({d + "/missing"}), hil::ConfigError);
  fs::create_directories(dir / "empty");
  CHECK_THROWS_AS(collect_scenario_files({d + "/empty"}), hil::ConfigError);
  // A file given by name runs whatever it is called: the loader judges it.
  CHECK(collect_scenario_files({d + "/notes.txt"}).size() == 1);
}

TEST_CASE("RIG-9 a run's summary reads back as written", "[suite]") {
  const fs::path dir = fresh_folder("summary");
  RunSummary s;
  s.scenario_file = "scenarios/x.yaml";
  s.name = "x: \"quoted\"";
  s.requirements = {"RIG-5", "DDTG-4"};
  s.outcome = Outcome::failed;
  s.simulated_s = 1.25;
  s.wall_s = 0.5;
  s.first_failure = "plc_sim: FAIL at cycle 12:\n  two lines";
  s.run_dir = "runs/x";
  write_run_summary(s, (dir / "summary.yaml").string());
  const RunSummary r = read_run_summary((dir / "summary.yaml").string());
  CHECK(r.scenario_file == s.scenario_file);
  CHECK(r.name == s.name);
  CHECK(r.requirements == s.requirements);
  CHECK(r.outcome == Outcome::failed);
  CHECK(r.simulated_s == 1.25);
  CHECK(r.real_time_factor() == 2.5);
  CHECK(r.first_failure == s.first_failure);
  std::ofstream(dir / "other.yaml") << "a: 1\n";
  CHECK_THROWS(read_run_summary((dir / "other.yaml").string()));
}

TEST_CASE("RIG-9 JUnit text escapes markup and characters XML forbids", "[suite]") {
  CHECK(escape_markup("a<b & \"c\" 'd'>") == "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;");
  CHECK(escape_markup(std::string("x\x01y\tz\n")) == "x\xEF\xBF\xBDy\tz\n");
}

TEST_CASE("RIG-9 a suite passes only without failures and errors", "[suite]") {
  SuiteResult suite;
  suite.runs.resize(2);
  suite.runs[0].outcome = Outcome::passed;
  suite.runs[1].outcome = Outcome::skipped;
  CHECK(suite.passed());
  suite.runs[1].outcome = Outcome::error;
  CHECK_FALSE(suite.passed());
  suite.runs[1].outcome = Outcome::failed;
  CHECK_FALSE(suite.passed());
  const std::string table = format_summary_table(suite);
  CHECK(table.find("suite: FAILED") != std::string::npos);
}

TEST_CASE("RIG-5 a suite's run folders mirror the scenario paths", "[suite]") {
  CHECK(run_dir_of("runs/s", "scenarios/ddtg/a.yaml") == "runs/s/scenarios/ddtg/a");
  CHECK(run_dir_of("runs/s", "/abs/b.yaml") == "runs/s/abs/b");
  CHECK(run_dir_of("runs/s", "./c.yml") == "runs/s/c");
}
