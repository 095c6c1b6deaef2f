// mrd-table4-run: the paper's Table 4 test on the simulated damper, with and without
// hysteresis compensation. Prints B-tracking and force figures and writes a
// force-displacement plot like the paper's Figure 14.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>

#include "common/cli/command_line.hpp"
#include "tools/table4/table4_report.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Simulated Table 4 run through the observer and the hysteresis compensator"};
  mrd::cli::set_up(app, "mrd-table4-run");
  mrd::tools::Table4RunOptions options;
  double amplitude_mm = 40.0;
  double rate_hz = 1000.0;
  std::string out_dir = "out";
  bool no_plot = false;
  app.add_option("--frequency", options.profile.frequency, "sine frequency [Hz]")
      ->check(mrd::cli::finite_in(0.001, 50.0))->capture_default_str();
  app.add_option("--amplitude-mm", amplitude_mm, "sine amplitude [mm]")
      ->check(mrd::cli::finite_in(0.1, 100.0))->capture_default_str();
  app.add_option("--rate", rate_hz, "control rate [Hz]")->check(mrd::cli::finite_in(10.0, 100000.0))
      ->capture_default_str();
  app.add_option("--cycles", options.cycles, "cycles to run (the first is excluded from figures)")
      ->check(CLI::Range(2, 1000))->capture_default_str();
  double lvdt_noise_um = 5.0;
  app.add_option("--lvdt-noise-um", lvdt_noise_um, "LVDT noise RMS [um]")
      ->check(mrd::cli::finite_in(0.0, 1000.0))->capture_default_str();
  app.add_option("--out", out_dir, "folder of results: table4_run.csv and the plot")->capture_default_str();
  app.add_flag("--no-plot", no_plot, "skip the PNG (it goes into --out)");
  bool bipolar = false;
  app.add_flag("--bipolar", bipolar, "a driver that can also push negative current (-Imax..Imax)");
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;
  options.lvdt_noise_rms = lvdt_noise_um * 1e-6;

  options.profile.amplitude = amplitude_mm * 1e-3;
  options.controller.observer.sample_period = 1.0 / rate_hz;
  if (bipolar) options.controller.limits.min_current = -options.controller.limits.max_current;
  const auto report = mrd::control::validate(options.controller);
  if (!report.ok()) {
    std::fprintf(stderr, "mrd-table4-run: invalid configuration\n%s", report.to_string().c_str());
    return mrd::cli::kUsage;
  }
  if (!mrd::cli::prepare_output_directory("mrd-table4-run", out_dir)) return mrd::cli::kIo;

  return mrd::tools::report_table4_comparison(options, out_dir, !no_plot);
}
