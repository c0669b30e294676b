#include "command_line.hpp"

#include <string_view>

#include "hil_build_version.hpp"

namespace hil {

std::string build_version() { return std::string(HIL_PROJECT_VERSION) + " (git " + HIL_GIT_HASH + ")"; }

namespace {
// A subcommand's --help shows its own footer only: the program's, where it has none.
void give_footer_to_subcommands(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    if (sub->get_footer().empty()) sub->footer(app.get_footer());
    give_footer_to_subcommands(*sub);
  }
}
}  // namespace

std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv) {
  std::string_view program = argc > 0 ? argv[0] : "hil";
  program = program.substr(program.rfind('/') + 1);  // npos + 1 == 0
  app.set_version_flag("--version", std::string(program) + " " + build_version());
  if (app.get_footer().empty())
    app.footer("Documentation: README.md and docs/ in the source tree (docs/SCENARIOS.md, docs/SUITES.md, "
               "docs/EXPORT.md, docs/ARCHITECTURE.md)");
  give_footer_to_subcommands(app);
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
}

}  // namespace hil
