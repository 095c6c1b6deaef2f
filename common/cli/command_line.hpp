#pragma once

// What every mrd program's command line shares (docs/ARCHITECTURE.md, "Command-line programs"):
// --version, the exit codes and the --help footer that states them, parse errors mapped to the
// usage code, and output folders created up front so a bad --out or --plot fails before the work.
#include <CLI/CLI.hpp>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "common/cli/exit_code.hpp"

namespace mrd::cli {

// "0.1.0 (git 2faff6d)" from a checkout, "0.1.0" from a tarball without .git.
[[nodiscard]] std::string version();

// The --help footer naming the exit codes.
[[nodiscard]] std::string exit_code_footer();

// Adds --version ("<program> <version>", what help2man reads) and the exit-code footer.
void set_up(CLI::App& app, std::string_view program);

// Parses; nullopt to go on, otherwise the status to exit with: 0 after --help or --version,
// kUsage after a parse or validation error (CLI11's own codes would be 105, 109, ...).
[[nodiscard]] std::optional<int> parse(CLI::App& app, int argc, const char* const* argv);

// Checks, before the work, that FILE can be written: not a folder, its folder there and writable
// (or the file itself writable). False, with "<program>: cannot write FILE: <reason>" on stderr
// (the system's reason: a folder, no such folder, permission denied): exit with kIo then.
[[nodiscard]] bool check_output_file(std::string_view program, const std::string& file);

// Every output of a run, before its work: each file (check_output_file), then each folder
// (prepare_output_directory), so a refused file leaves no folder behind. Empty paths are not
// asked for. False after the first that fails (its reason on stderr): exit with kIo then.
[[nodiscard]] bool check_outputs(std::string_view program, std::initializer_list<const std::string*> files,
                                 std::initializer_list<const std::string*> folders);

// A validator for a finite number in [lo, hi] ("--threshold: 1.5 is not in [0, 0.99]"); CLI11's
// own Range lets nan and inf through the conversion of some options.
[[nodiscard]] CLI::Validator finite_in(double lo, double hi);

// Creates the folder (and its parents) for --out or --plot. False, with the reason on stderr
// prefixed by the program's name, when it cannot be created or written: exit with kIo then.
[[nodiscard]] bool prepare_output_directory(std::string_view program, const std::string& directory);

}  // namespace mrd::cli
