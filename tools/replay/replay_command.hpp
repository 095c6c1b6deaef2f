#pragma once

// mrd-replay's work as one library function: read the run, replay it through the control law,
// print the summary and write what was asked. Its main (mrd_replay.cpp) declares the options and
// calls run_replay_command.
#include <optional>
#include <string>

#include "config/config_loader.hpp"
#include "tools/replay/replay.hpp"
#include "tools/replay/run_options_cli.hpp"

namespace mrd::tools {

// mrd-replay's command line, as parsed.
struct ReplayArguments {
  std::string run_path, plot_dir, csv_path, json_path, candump_path, report_dir;
  ReplayOptions replay_options;
  RunOptionsCli run_options;
  std::optional<double> zero_phase_cutoff;  // [Hz], --zero-phase-velocity when given
};

// Throws record::InputError for a run or a column mapping that cannot be read; otherwise the exit
// code (common/cli/exit_code.hpp). argc and argv are the command line, for the report.
int run_replay_command(const ReplayArguments& args, const mrd::config::LoadedConfig& config, int argc, char** argv);

}  // namespace mrd::tools
