// KRN-8 (issue 34): how long the decoder takes for each program of the
// corpus tests/programs/ (real-style CAM and shop programs): the best of
// --repeat whole decodes, per program and per block. Prints figures only.
#include <CLI/CLI.hpp>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "command_line.hpp"
#include "decoder.hpp"
#include "machine_config.hpp"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  CLI::App app("decode time of the NC program corpus (KRN-8)");
  std::string dir = std::string(HIL_SOURCE_DIR) + "/tests/programs";
  std::string machine_file = std::string(HIL_SOURCE_DIR) + "/config/xyz_machine.yaml";
  int repeat = 20;
  app.add_option("--dir", dir, "folder of .nc programs")->capture_default_str();
  app.add_option("--machine", machine_file, "machine file")->capture_default_str();
  app.add_option("--repeat", repeat, "decodes per program; the best is printed")->check(CLI::Range(1, 100000));
  app.footer("Documentation: docs/DIALECT.md in the source tree");
  HIL_PARSE_COMMAND_LINE(app, argc, argv);
  const hil::MachineConfig machine = hil::parse_machine_config(YAML::LoadFile(machine_file));
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".nc") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::printf("%-24s %7s %7s %10s %10s\n", "program", "lines", "blocks", "decode ms", "us/block");
  int failed = 0;
  for (const fs::path& file : files) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    const std::string program = text.str();
    double best = 1e300;
    size_t blocks = 0;
    for (int k = 0; k < repeat; ++k) {
      const auto start = std::chrono::steady_clock::now();
      const hil::cnc::DecodedProgram p =
          hil::cnc::decode_program(program, machine, std::vector<double>(machine.axes.size(), 0.0));
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      blocks = p.blocks.size();
      if (p.error && k == 0) {
        std::printf("%s: %s\n", file.filename().c_str(), hil::describe(*p.error).c_str());
        ++failed;
      }
    }
    const auto lines = std::count(program.begin(), program.end(), '\n');
    std::printf("%-24s %7ld %7zu %10.3f %10.2f\n", file.filename().c_str(), static_cast<long>(lines), blocks,
                best * 1e3, blocks ? best * 1e6 / static_cast<double>(blocks) : 0.0);
  }
  return failed ? 1 : 0;
}
