#include "run_page.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "html.hpp"
#include "report.hpp"
#include "root_cause.hpp"

namespace hil::rig {
namespace {

namespace fs = std::filesystem;

// More rows than anyone reads in a browser; report.txt has them all.
constexpr size_t max_event_rows = 2000;

std::string e(const std::string& text) { return escape_markup(text); }

std::string number(double value, int digits) {
  std::ostringstream o;
  o.precision(digits);
  o << std::fixed << value;
  return o.str();
}

std::string verdict_head(const std::string& title, bool passed, const std::vector<std::string>& because) {
  const std::string verdict = passed ? "PASSED" : "FAILED";
  std::string out = "<h1>" + e(title) + "</h1>\n<p><span class=\"verdict " + verdict + "\">" + verdict +
                    "</span></p>\n";
  if (!because.empty()) {
    out += "<ul class=\"because\">\n";
    for (const std::string& reason : because) out += "<li>because " + e(reason) + "</li>\n";
    out += "</ul>\n";
  }
  return out;
}

std::string plots_section(const PagePlots& plots) {
  std::string out = "<h2>Plots</h2>\n";
  size_t shown = 0;
  for (const std::string& image : plots.images) {
    // The SVG beside a PNG, where gnuplot drew one: zoomable, sharp at any zoom.
    const std::string svg = data_uri(fs::path(image).replace_extension(".svg").string(), "image/svg+xml");
    const std::string uri = svg.empty() ? data_uri(image, "image/png") : svg;
    if (uri.empty()) continue;
    const std::string name = fs::path(image).filename().string();
    out += svg.empty() ? "<figure><img src=\"" + uri + "\" alt=\"" + e(name) + "\"><figcaption>" + e(name) +
                             "</figcaption></figure>\n"
                       : "<figure><div class=\"zoom\"><img src=\"" + uri + "\" alt=\"" + e(name) +
                             "\"></div><figcaption>" + e(name) +
                             " (wheel: zoom, drag: pan, double click: back)</figcaption></figure>\n";
    ++shown;
  }
  if (shown == 0) out += "<p>No plots: " + e(plots.note.empty() ? "none drawn" : plots.note) + "</p>\n";
  return out;
}

std::string text_report(const std::string& report) {
  return "<h2>Text report</h2>\n<details><summary>report.txt</summary>\n" + html_pre(report) + "</details>\n";
}

std::string row(const std::vector<std::string>& cells) {
  std::string out = "<tr>";
  for (const std::string& c : cells) out += "<td>" + e(c) + "</td>";
  return out + "</tr>\n";
}

// The offline check's per-axis limits and its violations as tables (issue 37: was a <pre>).
std::string limits_section(const logger::CheckReport& check) {
  std::ostringstream b;
  b << "<table>\n<tr><th>axis</th><th>quantity</th><th>max</th><th>limit</th><th>margin</th></tr>\n";
  for (const AxisLimits& axis : limit_table(check)) {
    for (size_t i = 0; i < axis.rows.size(); ++i) {
      const LimitRow& r = axis.rows[i];
      b << "<tr><td>" << (i == 0 ? e(axis.axis) : "") << "</td><td>" << e(r.quantity) << "</td><td class=\"num\">"
        << number(r.value, 4) << "</td><td class=\"num\">" << (r.limit > 0 ? number(r.limit, 4) : "-")
        << "</td><td class=\"num" << (r.limit > 0 && r.margin_percent < 0 ? " over" : "") << "\">"
        << (r.limit > 0 ? number(r.margin_percent, 1) + " %" : "-") << "</td></tr>\n";
    }
    if (!axis.note.empty()) b << "<tr><td></td><td colspan=\"4\">" << e(axis.note) << "</td></tr>\n";
  }
  b << "</table>\n<p>limit violations: " << check.violations.size() << "</p>\n";
  if (!check.violations.empty()) {
    b << "<table>\n<tr><th>axis</th><th>quantity</th><th>from [s]</th><th>to [s]</th><th>cycles</th><th>worst</th>"
         "<th>at [s]</th><th>limit</th></tr>\n";
    for (const logger::Violation& v : check.violations)
      b << "<tr class=\"violation\"><td>" << e(v.axis) << "</td><td>" << e(v.quantity) << "</td><td class=\"num\">"
        << number(v.time_s, 4) << "</td><td class=\"num\">" << number(v.end_time_s, 4) << "</td><td class=\"num\">"
        << v.cycles << "</td><td class=\"num\">" << number(v.value, 4) << "</td><td class=\"num\">"
        << number(v.worst_time_s, 4) << "</td><td class=\"num\">" << number(v.limit, 4) << "</td></tr>\n";
    b << "</table>\n";
  }
  return b.str();
}

void write(const std::string& dir, const std::string& title, const std::string& body) {
  std::ofstream(fs::path(dir) / "report.html") << html_page(title, body);
}

}  // namespace

void write_run_page(const Scenario& scenario, const RunResult& result, const logger::RunVerdict& verdict,
                    const logger::RunLog& log, const logger::CheckReport* check, const PagePlots& plots) {
  std::ostringstream b;
  std::string title = "scenario " + scenario.name;
  for (size_t i = 0; i < scenario.requirements.size(); ++i)
    title += (i ? " " : " (") + scenario.requirements[i] + (i + 1 == scenario.requirements.size() ? ")" : "");
  b << verdict_head(title, result.passed, verdict.reasons);
  if (!scenario.description.empty()) b << "<p>" << e(scenario.description) << "</p>\n";

  const bool logged = !log.messages_per_channel.empty();
  int64_t messages = 0;
  for (const auto& entry : log.messages_per_channel) messages += entry.second;
  const std::vector<std::string> problems = logger::log_problems(log.facts);
  b << "<h2>Run</h2>\n<table>\n"
    << "<tr><th>run folder</th><td>" << e(result.run_dir) << " (<a href=\"report.txt\">report.txt</a>"
    << (logged ? ", <a href=\"run.lcmlog\">run.lcmlog</a>" : "") << ")</td></tr>\n";
  if (logged) {
    b << "<tr><th>simulated</th><td>" << log.last_cycle + 1 << " cycles = " << number(result.simulated_s, 3)
      << " s in " << number(result.wall_s, 2) << " s wall, "
      << number(result.wall_s > 0 ? result.simulated_s / result.wall_s : 0, 1) << " x real time</td></tr>\n"
      << "<tr><th>log</th><td>" << messages << " messages; complete: "
      << (problems.empty() ? "yes" : "NO: " + e(std::to_string(problems.size()) + " problem(s)")) << "</td></tr>\n"
      << "<tr><th>refused traffic</th><td>" << e(logger::describe_refused(log.facts)) << "</td></tr>\n";
  } else {
    b << "<tr><th>log</th><td>none: the run left no log</td></tr>\n";
  }
  b << "</table>\n";
  if (!problems.empty() && logged) {
    b << "<ul>\n";
    for (const std::string& p : problems) b << "<li>" << e(p) << "</li>\n";
    b << "</ul>\n";
  }

  const double dt = scenario.machine.cycle_time_s();
  b << "<h2>Expectations</h2>\n<p>" << e(describe_expectation_counts(log.facts)) << "</p>\n";
  std::string expectations;
  for (const logger::LoggedEvent& ev : log.events) {
    if (ev.event.verdict == Verdict::none) continue;
    const std::string v = ev.event.verdict == Verdict::pass ? "PASS" : "FAIL";
    expectations += "<tr><td class=\"" + v + "\">" + v + "</td><td class=\"num\">" + std::to_string(ev.cycle) +
                    "</td><td class=\"num\">" + number(ev.cycle * dt, 4) + "</td><td>" + e(ev.source) + "</td><td>" +
                    e(ev.event.message) + "</td></tr>\n";
  }
  if (!expectations.empty())
    b << "<table>\n<tr><th>verdict</th><th>cycle</th><th>t [s]</th><th>source</th><th>expectation</th></tr>\n"
      << expectations << "</table>\n";

  if (log.facts.realtime || log.real_time) b << "<h2>Real time</h2>\n" << html_pre(format_real_time(log));

  b << "<h2>Limits (offline check)</h2>\n";
  if (check) b << limits_section(*check);
  else b << "<p>" << (logged ? "The log has no scenario (HIL_SCENARIO): no limits to check against." : "No log.")
         << "</p>\n";

  int warnings = 0;
  for (const auto& ev : log.events) warnings += ev.event.severity == Severity::warning ? 1 : 0;
  b << "<h2>Events</h2>\n<p>" << count_errors(log) << " errors, " << warnings << " warnings, " << log.events.size()
    << " events in all</p>\n";
  if (!log.events.empty()) {
    b << "<table>\n<tr><th>cycle</th><th>t [s]</th><th>source</th><th>event</th></tr>\n";
    for (size_t i = 0; i < log.events.size() && i < max_event_rows; ++i) {
      const logger::LoggedEvent& ev = log.events[i];
      b << row({std::to_string(ev.cycle), number(ev.cycle * dt, 4), ev.source, describe(ev.event)});
    }
    b << "</table>\n";
    if (log.events.size() > max_event_rows) b << "<p>... and more: report.txt lists them all.</p>\n";
  }
  b << plots_section(plots) << text_report(result.report);
  write(result.run_dir, title, b.str());
}

void write_set_page(const ScenarioSet& set, const RunResult& result, const std::vector<VariantFigures>& figures,
                    const std::string& comparisons, const PagePlots& plots) {
  std::vector<std::string> because;
  for (const VariantFigures& f : figures)
    if (!f.passed) because.push_back("variant " + f.name + " failed");
  if (comparisons.find("FAILS") != std::string::npos) because.push_back("a comparison of the variants fails");
  const std::string title = "scenario " + set.name + " (" + std::to_string(set.variants.size()) + " variants)";
  std::ostringstream b;
  b << verdict_head(title, result.passed, because) << "<h2>Variants</h2>\n<table>\n<tr><th>variant</th><th>verdict</th></tr>\n";
  for (const VariantFigures& f : figures) {
    const std::string v = f.passed ? "PASSED" : "FAILED";
    b << "<tr><td><a href=\"" << e(f.name) << "/report.html\">" << e(f.name) << "</a></td><td class=\"" << v << "\">"
      << v << "</td></tr>\n";
  }
  b << "</table>\n" << html_pre(format_variants(figures)) << "<h2>Comparisons</h2>\n"
    << (comparisons.empty() ? std::string("<p>none</p>\n") : html_pre(comparisons)) << plots_section(plots)
    << text_report(result.report);
  write(result.run_dir, title, b.str());
}

}  // namespace hil::rig
