#pragma once

// The parts of a program's command line that need no CLI11: the version, the exit codes and
// their --help footer, and the checks of output files and folders before the work.
#include <initializer_list>
#include <string>
#include <string_view>

#include "common/cli/exit_code.hpp"

namespace mrd::cli {

// "0.1.0 (git 2faff6d)" from a checkout, "0.1.0" from a tarball without .git.
[[nodiscard]] std::string version();

// The --help footer naming the exit codes.
[[nodiscard]] std::string exit_code_footer();

// Checks, before the work, that FILE can be written: not a folder, its folder there and writable
// (or the file itself writable). False, with "<program>: cannot write FILE: <reason>" on stderr
// (the system's reason: a folder, no such folder, permission denied): exit with kIo then.
[[nodiscard]] bool check_output_file(std::string_view program, const std::string& file);

// Every output of a run, before its work: each file (check_output_file), then each folder
// (prepare_output_directory), so a refused file leaves no folder behind. Empty paths are not
// asked for. False after the first that fails (its reason on stderr): exit with kIo then.
[[nodiscard]] bool check_outputs(std::string_view program, std::initializer_list<const std::string*> files,
                                 std::initializer_list<const std::string*> folders);

// Creates the folder (and its parents) for --out or --plot. False, with the reason on stderr
// prefixed by the program's name, when it cannot be created or written: exit with kIo then.
[[nodiscard]] bool prepare_output_directory(std::string_view program, const std::string& directory);

}  // namespace mrd::cli
