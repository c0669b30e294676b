#pragma once
// Which scenario files a suite runs (RIG-5, RIG-9): the files and folders
// given to `hil run`, and the K-th of N deterministic slices of them, so
// that a CI matrix or an Indexed Job spreads a suite without a scheduler of
// ours.
#include <string>
#include <vector>

namespace hil::rig {

// --shard K/N: 1 <= K <= N.
struct Shard {
  int index = 1;
  int count = 1;
};

// "K/N"; throws ConfigError for anything else.
Shard parse_shard(const std::string& text);

// Files as given; folders recursively, every *.yaml / *.yml in them, in
// path order; each file once. Throws ConfigError for a path that does not
// exist or a folder without scenario files.
std::vector<std::string> collect_scenario_files(const std::vector<std::string>& paths);

// Every N-th file from the K-th on: the same files for the same suite on any
// machine, slices of nearly equal size, and a folder's scenarios spread over
// the shards rather than all in one.
std::vector<std::string> shard_of(const std::vector<std::string>& files, Shard shard);

}  // namespace hil::rig
