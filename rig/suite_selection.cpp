#include "suite_selection.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "scenario_set.hpp"

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

// A file's name without running it: "" if the loader refuses the file (its
// run says why).
std::string scenario_name(const std::string& file) {
  try {
    return load_scenario_set(file).name;
  } catch (const std::exception&) {
    return "";
  }
}

std::set<std::string> read_record() {
  std::set<std::string> failed;
  std::ifstream in(last_failed_file);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) failed.insert(line);
  return failed;
}

std::string key_of(const std::string& file) { return fs::path(file).lexically_normal().string(); }

}  // namespace

std::vector<std::string> matching(const std::vector<std::string>& files, const std::vector<std::string>& patterns) {
  if (patterns.empty()) return files;
  std::vector<std::string> out;
  for (const std::string& file : files) {
    const std::string text = lower(file) + "\n" + lower(scenario_name(file));
    bool wanted = false, excluded = false, any_positive = false;
    for (const std::string& pattern : patterns) {
      const bool negated = pattern.rfind("not ", 0) == 0;
      const std::string part = lower(negated ? pattern.substr(4) : pattern);
      const bool found = text.find(part) != std::string::npos;
      if (negated) excluded = excluded || found;
      else {
        any_positive = true;
        wanted = wanted || found;
      }
    }
    if ((wanted || !any_positive) && !excluded) out.push_back(file);
  }
  return out;
}

std::vector<std::string> last_failed(const std::vector<std::string>& files, std::string& note) {
  const std::set<std::string> failed = read_record();
  std::vector<std::string> out;
  for (const std::string& file : files)
    if (failed.count(key_of(file))) out.push_back(file);
  if (out.empty()) {
    note = std::string("--lf: ") + (failed.empty() ? "no failures recorded in " : "none of these failed by ") +
           last_failed_file + ": running all";
    return files;
  }
  return out;
}

void record_failures(const SuiteResult& suite) {
  std::set<std::string> failed = read_record();
  for (const RunSummary& r : suite.runs) {
    if (r.outcome == Outcome::failed || r.outcome == Outcome::error) failed.insert(key_of(r.scenario_file));
    else if (r.outcome == Outcome::passed) failed.erase(key_of(r.scenario_file));
  }
  std::error_code ec;
  fs::create_directories(fs::path(last_failed_file).parent_path(), ec);
  std::ofstream out(last_failed_file);
  for (const std::string& file : failed) out << file << '\n';
}

std::string list_scenarios(const std::vector<std::string>& files) {
  std::ostringstream out;
  for (const std::string& file : files) {
    out << file;
    try {
      const ScenarioSet set = load_scenario_set(file);
      out << "  " << set.name;
      if (set.has_variants()) out << " (" << set.variants.size() << " variants)";
      const std::vector<std::string>& ids = set.variants.front().scenario.requirements;
      if (!ids.empty()) {
        out << "  [";
        for (size_t i = 0; i < ids.size(); ++i) out << (i ? " " : "") << ids[i];
        out << "]";
      }
    } catch (const std::exception& e) {
      out << "  (refused: " << e.what() << ")";
    }
    out << '\n';
  }
  out << files.size() << " scenario(s)\n";
  return out.str();
}

}  // namespace hil::rig
