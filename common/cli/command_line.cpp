#include "common/cli/command_line.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

namespace {

// CLI11 says "Could not convert: --threshold = abc"; an engineer reads "not a number".
std::optional<std::string> not_a_number(const CLI::ConversionError& e) {
  const std::string text = e.what();
  const std::string prefix = "Could not convert: ";
  const auto eq = text.find(" = ");
  if (!text.starts_with(prefix) || eq == std::string::npos) return std::nullopt;
  return text.substr(prefix.size(), eq - prefix.size()) + ": '" + text.substr(eq + 3) + "' is not a number";
}

// CLI11 reads "-1" into an unsigned count or seed as 2^64 - 1, and a number past 2^64 - 1 as
// 2^64 - 1 too; every unsigned option of the app and its subcommands refuses a sign or such a
// number instead. The validator has no description, so --help keeps its text.
void refuse_wrapping_unsigned(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    if (!option->get_type_name().starts_with("UINT")) continue;
    option->check(CLI::Validator(
        [](std::string& text) {
          if (!text.empty() && text.front() == '-') return text + " is negative: a count or a seed is 0 or more";
          errno = 0;
          std::strtoull(text.c_str(), nullptr, 0);  // as CLI11 reads it
          return errno == ERANGE ? text + " is too large: a count or a seed is at most 2^64 - 1" : std::string();
        },
        ""));
  }
  for (CLI::App* sub : app.get_subcommands({})) refuse_wrapping_unsigned(*sub);
}

// CLI11's Range on a whole-number option says "Value abc not in range 2 to 1000" for text that
// is no number at all, or 2.5; every integer option says "not a whole number" first instead
// (as strtoll reads it, so 0x20 stays a number). Put in front of the option's own checks; no
// description, so --help keeps its text.
void refuse_non_integers(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    if (!type.starts_with("INT") && !type.starts_with("UINT")) continue;
    option->transform(CLI::Validator(
        [](std::string& text) {
          char* end = nullptr;
          errno = 0;
          (void)std::strtoll(text.c_str(), &end, 0);
          const bool whole = !text.empty() && end != nullptr && *end == '\0';
          return whole || errno == ERANGE ? std::string() : "'" + text + "' is not a whole number";
        },
        ""));
  }
  for (CLI::App* sub : app.get_subcommands({})) refuse_non_integers(*sub);
}

}  // namespace

CLI::Validator finite_in(double lo, double hi) {
  char range[96];
  std::snprintf(range, sizeof range, "in [%g, %g]", lo, hi);
  return CLI::Validator(
      [lo, hi, range = std::string(range)](std::string& text) {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0') return "'" + text + "' is not a number";
        if (!std::isfinite(v) || v < lo || v > hi) return text + " is not " + range;
        return std::string();
      },
      "FLOAT " + std::string(range));
}

bool check_output_file(std::string_view program, const std::string& file) {
  namespace fs = std::filesystem;
  if (file.empty()) return true;
  std::error_code ec;
  const fs::path path(file);
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (fs::is_directory(path, ec)) {
    ec = std::make_error_code(std::errc::is_a_directory);
  } else if (fs::exists(path, ec)) {
    if (::access(file.c_str(), W_OK) != 0) ec = std::error_code(errno, std::generic_category());
  } else if (!fs::exists(folder, ec)) {
    // A plain file on the way reads as "not a folder", the rest as "no such folder".
    fs::path up = folder;
    while (up.has_parent_path() && !fs::exists(up, ec) && up != up.parent_path()) up = up.parent_path();
    ec = fs::exists(up, ec) && !fs::is_directory(up, ec) ? std::make_error_code(std::errc::not_a_directory)
                                                         : std::make_error_code(std::errc::no_such_file_or_directory);
  } else if (!fs::is_directory(folder, ec)) {
    ec = std::make_error_code(std::errc::not_a_directory);
  } else if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    ec = std::error_code(errno, std::generic_category());
  }
  if (!ec) return true;
  std::fprintf(stderr, "%.*s: cannot write %s: %s\n", static_cast<int>(program.size()), program.data(), file.c_str(),
               ec.message().c_str());
  return false;
}

bool check_outputs(std::string_view program, std::initializer_list<const std::string*> files,
                   std::initializer_list<const std::string*> folders) {
  for (const std::string* file : files)
    if (!check_output_file(program, *file)) return false;
  for (const std::string* folder : folders)
    if (!folder->empty() && !prepare_output_directory(program, *folder)) return false;
  return true;
}

std::optional<int> parse(CLI::App& app, int argc, const char* const* argv) {
  refuse_wrapping_unsigned(app);
  refuse_non_integers(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --help-all, --version
    return app.exit(e);
  } catch (const CLI::ConversionError& e) {
    if (const auto why = not_a_number(e)) {
      std::fprintf(stderr, "%s\nRun with --help for more information.\n", why->c_str());
      return kUsage;
    }
    app.exit(e);
    return kUsage;
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
