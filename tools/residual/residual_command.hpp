#pragma once

// mrd-residual's work as library functions: check the outputs, analyse the runs (the base fit and
// the search for missing effects), print the summary and write what was asked. Its main
// (mrd_residual.cpp) declares the options and calls run_residual_command.
#include <string>
#include <vector>

#include "config/config_loader.hpp"
#include "tools/replay/run_options_cli.hpp"
#include "tools/residual/fit_series.hpp"
#include "tools/residual/residual_result.hpp"

namespace mrd::tools {

// mrd-residual's command line, as parsed; the analysis completes the options with the config and the --no- flags.
struct ResidualArguments {
  std::vector<std::string> run_paths;
  std::string json_path, plot_dir, config_out, report_dir;
  FitSeriesOptions series_options;
  ResidualOptions options;
  RunOptionsCli run_options;
  bool accept_unphysical = false;
  bool spencer = false;
  bool no_screening = false;
  bool no_discovery = false;
  bool quiet = false;
};

// Checks the outputs, then analyses, prints and writes; the exit code (common/cli/exit_code.hpp).
// argc and argv are the command line, for the report's provenance.
int run_residual_command(const ResidualArguments& args, const mrd::config::LoadedConfig& config, int argc,
                         char** argv);

}  // namespace mrd::tools
