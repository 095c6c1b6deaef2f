#include "common/cli/command_line.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

namespace mrd::cli {

// Generated at build time (cmake/version.cmake): the project's version and git revision.
extern const char* const kProjectVersion;
extern const char* const kGitRevision;

std::string version() {
  std::string text = kProjectVersion;
  if (*kGitRevision != '\0') text += std::string(" (git ") + kGitRevision + ")";
  return text;
}

std::string exit_code_footer() {
  return "Exit status: 0 ok, 1 usage or config error, 2 bad input file, 3 I/O error (an output, "
         "folder or bus that cannot be opened or written).";
}

void set_up(CLI::App& app, std::string_view program) {
  app.set_version_flag("--version", std::string(program) + " " + version(),
                       "print the program's version and exit");
  app.footer(exit_code_footer());
}

std::optional<int> parse(CLI::App& app, int argc, const char* const* argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --help-all, --version
    return app.exit(e);
  } catch (const CLI::Error& e) {
    app.exit(e);  // prints the message and the hint to run --help
    return kUsage;
  }
  return std::nullopt;
}

bool prepare_output_directory(std::string_view program, const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (!ec && !fs::is_directory(directory, ec)) ec = std::make_error_code(std::errc::not_a_directory);
  if (!ec && ::access(directory.c_str(), W_OK) != 0) ec = std::error_code(errno, std::generic_category());
  if (ec) {
    std::fprintf(stderr, "%.*s: cannot write to folder %s: %s\n", static_cast<int>(program.size()),
                 program.data(), directory.c_str(), ec.message().c_str());
    return false;
  }
  return true;
}

}  // namespace mrd::cli
