#pragma once

// What every mrd program's command line shares (docs/ARCHITECTURE.md, "Command-line programs"):
// --version, the exit codes and the --help footer that states them, parse errors mapped to the
// usage code, and output folders created up front so a bad --out or --plot fails before the work.
// The parts without CLI11 are in common/cli/program_outputs.hpp: a file that only checks its
// outputs or names the version includes that, not CLI11 (about 8 s of compile per file).
#include <CLI/CLI.hpp>

#include <optional>
#include <string_view>

#include "common/cli/program_outputs.hpp"

namespace mrd::cli {

// Adds --version ("<program> <version>", what help2man reads) and the exit-code footer.
void set_up(CLI::App& app, std::string_view program);

// Parses; nullopt to go on, otherwise the status to exit with: 0 after --help or --version,
// kUsage after a parse or validation error (CLI11's own codes would be 105, 109, ...).
[[nodiscard]] std::optional<int> parse(CLI::App& app, int argc, const char* const* argv);

// A validator for a finite number in [lo, hi] ("--threshold: 1.5 is not in [0, 0.99]"); CLI11's
// own Range lets nan and inf through the conversion of some options.
[[nodiscard]] CLI::Validator finite_in(double lo, double hi);

}  // namespace mrd::cli
