#include "command_line.hpp"

#include <string_view>

#include "hil_build_version.hpp"

namespace hil {

std::string build_version() { return std::string(HIL_PROJECT_VERSION) + " (git " + HIL_GIT_HASH + ")"; }

std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv) {
  std::string_view program = argc > 0 ? argv[0] : "hil";
  program = program.substr(program.rfind('/') + 1);  // npos + 1 == 0
  app.set_version_flag("--version", std::string(program) + " " + build_version());
  if (app.get_footer().empty())
    app.footer("Documentation: README.md and docs/ in the source tree (docs/SCENARIOS.md, docs/SUITES.md, "
               "docs/EXPORT.md, docs/ARCHITECTURE.md)");
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
