// jerk_cases IN.csv OUT.csv: plans every row (p0,v0,a0,pf,vf,af,vmax,amax,jmax,
// SI units) with the TRAPEZ position planner and writes the row back with
// `duration` and `ok` appended (KRN-3). ok = 1: the profile ends at rest on
// pf within 1e-9 and stays within the limits (profile_check.hpp). Rows with
// vf or af != 0, non-numbers or limits <= 0 get ok = 0 and duration nan.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "command_line.hpp"
#include "position_profile.hpp"
#include "profile_check.hpp"

namespace {

using namespace hil::cnc;

// Parses exactly nine numbers; false on anything else.
bool parse_row(const std::string& line, double (&x)[9]) {
  std::istringstream in(line);
  std::string field;
  int n = 0;
  while (std::getline(in, field, ',')) {
    if (n == 9) return false;
    char* end = nullptr;
    x[n] = std::strtod(field.c_str(), &end);
    while (end && (*end == ' ' || *end == '\r')) ++end;
    if (end == field.c_str() || (end && *end != '\0')) return false;
    ++n;
  }
  return n == 9;
}

std::string format(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"jerk_cases: plan 1-D TRAPEZ profiles for rows of a CSV file"};
  std::string in_path, out_path;
  app.add_option("in", in_path, "CSV with columns p0,v0,a0,pf,vf,af,vmax,amax,jmax")->required();
  app.add_option("out", out_path, "CSV written with duration,ok appended")->required();
  HIL_PARSE_COMMAND_LINE(app, argc, argv);

  std::ifstream in(in_path);
  if (!in) {
    std::cerr << "jerk_cases: cannot read " << in_path << '\n';
    return 2;
  }
  std::ofstream out(out_path);
  if (!out) {
    std::cerr << "jerk_cases: cannot write " << out_path << '\n';
    return 2;
  }
  std::string line;
  long rows = 0, ok_rows = 0, line_nr = 0;
  while (std::getline(in, line)) {
    ++line_nr;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    double x[9];
    if (!parse_row(line, x)) {
      if (line_nr == 1) {  // the header
        out << line << ",duration,ok\n";
        continue;
      }
      std::cerr << "jerk_cases: " << in_path << ':' << line_nr << ": not nine numbers\n";
      out << line << ",nan,0\n";
      ++rows;
      continue;
    }
    const MotionState start{x[0], x[1], x[2], 0};
    const double target = x[3];
    const Limits lim{x[6], x[7], x[8]};
    bool ok = x[4] == 0 && x[5] == 0 && lim.v > 0 && lim.a > 0 && lim.j > 0;
    for (double value : x) ok = ok && std::isfinite(value);
    double duration = NAN;
    if (ok) {
      const MotionProfile profile = position_profile(start, target, lim, SlopeType::trapez);
      duration = profile.duration();
      ok = meets(profile, target, lim, SlopeType::trapez);
    }
    out << line << ',' << format(duration) << ',' << (ok ? 1 : 0) << '\n';
    ++rows;
    ok_rows += ok ? 1 : 0;
  }
  std::cerr << "jerk_cases: " << rows << " rows, " << ok_rows << " ok\n";
  return 0;
}
