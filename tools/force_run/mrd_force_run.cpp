// mrd-force-run: issue 18's force-control comparison on the simulated damper. A desired force
// (band-limited random, or the clipped-optimal demand of a two-storey building in an earthquake)
// is played through four strategies on the same plant: Dyke's clipped on-off law, a static
// inverse on the anhysteretic curve, the J-A compensated inverse, and the same with the coil lag
// inverted. The controller's model is identified from noisy simulated measurements (default),
// the plant's own (matched) or a documented perturbation of it (docs/FORCE-CONTROL.md).
// The options are declared here; the comparison is tools/force_run/force_run_command.
#include <CLI/CLI.hpp>

#include "common/cli/command_line.hpp"
#include "common/cli/exit_code.hpp"
#include "tools/force_run/force_run_command.hpp"

namespace {

using Arguments = mrd::tools::ForceRunArguments;

void add_options(CLI::App& app, Arguments& a) {
  app.add_option("--profile", a.profile_choice, "desired-force profile")
      ->check(CLI::IsMember({"random", "structure"}))->capture_default_str();
  app.add_option("--case", a.case_choice, "the controller's model: the plant's own, identified on noisy runs, "
                                          "perturbed 10-20 %, or all three")
      ->check(CLI::IsMember({"matched", "identified", "perturbed", "all"}))->capture_default_str();
  app.add_option("--coil-lag-ms", a.coil_lag_ms, "the plant's coil lag time constant [ms], 0 for none")
      ->check(mrd::cli::finite_in(0.0, 200.0))->capture_default_str();
  app.add_option("--seed", a.seed, "seed of the profile, the noise and the identification")->capture_default_str();
  app.add_option("--duration", a.duration, "run length [s]; the first second is left out of the figures")
      ->check(mrd::cli::finite_in(2.0, 600.0))->capture_default_str();
  app.add_option("--force-noise-n", a.force_noise, "load-cell noise RMS [N] (the clipped law reads the load cell)")
      ->check(mrd::cli::finite_in(0.0, 1e4))->capture_default_str();
  app.add_option("--lqr-force-weight", a.lqr_force_weight, "structure profile: r, the LQR weight on the damper force "
                                                           "against the storey shears")
      ->check(mrd::cli::finite_in(1e-6, 1e6))->capture_default_str();
  app.add_option("--pga-g", a.pga_g, "structure profile: peak ground acceleration [g]")
      ->check(mrd::cli::finite_in(0.01, 2.0))->capture_default_str();
  app.add_option("--drift", a.drift_pct, "the plant's yield stress falls by PCT % over the run, as the fluid heats")
      ->check(mrd::cli::finite_in(0.0, 60.0))->capture_default_str();
  app.add_flag("--load-cell", a.load_cell, "add inverse_ja_load_cell: inverse_ja with the load-cell correction of "
                                           "its model's yield force");
  app.add_option("--load-cell-tau", a.load_cell_tau, "the correction's time constant [s]")
      ->check(mrd::cli::finite_in(0.01, 1000.0))->capture_default_str();
  app.add_option("--json", a.json_path, "write the figures as JSON to FILE");
  app.add_option("--out", a.out_dir, "folder for the CSV trace and the PNG plots (none without it)");
  app.add_flag("--no-plot", a.no_plot, "with --out, skip the PNGs");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Force tracking on the simulated damper: clipped on-off, static Bingham inverse, J-A inverse "
               "with and without the coil lag inverted"};
  Arguments args;
  add_options(app, args);
  mrd::cli::set_up(app, "mrd-force-run");
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;
  if (!mrd::cli::check_outputs("mrd-force-run", {&args.json_path}, {&args.out_dir})) return mrd::cli::kIo;
  return mrd::tools::run_force_comparison(args);
}
