#include "plots.hpp"

#include <filesystem>

#include "plot_export.hpp"
#include "process.hpp"

namespace hil::rig {

std::string draw_plots(const logger::RunLog& log, const logger::CheckReport& report, const std::string& dir,
                       std::vector<std::string>* drawn) {
  namespace fs = std::filesystem;
  logger::PlotFiles files;
  try {
    files = logger::write_plot_files(log, report, dir);
  } catch (const std::exception& e) {
    return std::string("plots: none (") + e.what() + ")";
  }
  const fs::path folder = fs::absolute(dir);
  std::string cd = "cd '";
  for (char c : folder.string()) cd += c == '\'' ? std::string("''") : std::string(1, c);
  cd += "'";
  Process gnuplot("gnuplot", {"gnuplot", "-e", cd, fs::absolute(files.script).string()},
                  (folder / "gnuplot.out").string());
  const std::optional<int> status = gnuplot.wait_for(std::chrono::seconds(120));
  const int code = status ? *status : gnuplot.stop();
  if (code == 127) return "plots: gnuplot not found (apt-get install gnuplot-nox); data and script in " + dir;
  if (code != 0) return "plots: gnuplot failed (" + (folder / "gnuplot.out").string() + ")";
  if (drawn) *drawn = files.images;
  std::string names;
  for (const auto& image : files.images) names += (names.empty() ? "" : ", ") + fs::path(image).filename().string();
  return "plots: " + dir + "/ (" + names + ")";
}

}  // namespace hil::rig
