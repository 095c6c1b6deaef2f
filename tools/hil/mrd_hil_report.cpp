// mrd-hil-report: a hardware-in-the-loop run in one page (tools/hil/hil_report.hpp).
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "common/cli/command_line.hpp"
#include "tools/hil/hil_report.hpp"

int main(int argc, char** argv) {
  CLI::App app{"mrd-hil-report: the controller's telemetry against the plant's log"};
  mrd::cli::set_up(app, "mrd-hil-report");
  mrd::tools::HilReportOptions options;
  app.add_option("--telemetry", options.telemetry_path, "mrd-controller's telemetry CSV")->required();
  app.add_option("--plant", options.plant_path, "mrd-plant's log (recorded-run CSV)")->required();
  app.add_option("--controller-t0", options.controller_t0,
                 "CLOCK_MONOTONIC [s] of the telemetry's time 0 (default: the file's time-origin line)")
      ->check(mrd::cli::finite_in(0.0, 1e12));
  app.add_option("--plant-t0", options.plant_t0,
                 "CLOCK_MONOTONIC [s] of the plant log's time 0 (default: the file's time-origin line)")
      ->check(mrd::cli::finite_in(0.0, 1e12));
  app.add_option("--plot", options.plot_dir, "folder for the force-displacement plot (force_displacement.png, its data .csv)");
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;
  if (!options.plot_dir.empty() && !mrd::cli::prepare_output_directory("mrd-hil-report", options.plot_dir))
    return mrd::cli::kIo;
  return mrd::tools::print_hil_report(options);
}
