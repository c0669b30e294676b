#include "scenario_files.hpp"

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>

#include "config_error.hpp"

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

bool is_scenario_file(const fs::path& p) {
  return fs::is_regular_file(p) && (p.extension() == ".yaml" || p.extension() == ".yml");
}

}  // namespace

Shard parse_shard(const std::string& text) {
  static const std::regex form(R"(([0-9]{1,6})/([0-9]{1,6}))");
  std::smatch m;
  if (std::regex_match(text, m, form)) {
    const Shard s{std::stoi(m[1]), std::stoi(m[2])};
    if (s.index >= 1 && s.index <= s.count) return s;
  }
  throw ConfigError("--shard " + text + ": expected K/N with 1 <= K <= N, e.g. 2/4");
}

std::vector<std::string> collect_scenario_files(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  std::set<fs::path> seen;
  auto add = [&](const fs::path& p) {
    if (seen.insert(fs::weakly_canonical(p)).second) files.push_back(p.lexically_normal().string());
  };
  for (const std::string& path : paths) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      std::vector<fs::path> found;
      for (const auto& entry : fs::recursive_directory_iterator(path, fs::directory_options::follow_directory_symlink))
        if (is_scenario_file(entry.path())) found.push_back(entry.path());
      if (found.empty()) throw ConfigError(path + ": a folder without scenario files (*.yaml)");
      std::sort(found.begin(), found.end());
      for (const fs::path& p : found) add(p);
    } else if (fs::exists(path, ec)) {
      add(path);  // whatever its name: the loader judges its content
    } else {
      throw ConfigError(path + ": no such file or folder");
    }
  }
  return files;
}

std::vector<std::string> shard_of(const std::vector<std::string>& files, Shard shard) {
  std::vector<std::string> slice;
  for (size_t i = static_cast<size_t>(shard.index - 1); i < files.size(); i += static_cast<size_t>(shard.count))
    slice.push_back(files[i]);
  return slice;
}

}  // namespace hil::rig
