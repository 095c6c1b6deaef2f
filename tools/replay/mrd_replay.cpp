// mrd-replay: runs the firmware's control law (schedule, J-A + Bingham observer, hysteresis
// compensator) over a recorded run, sample by sample, and compares the observer's force with
// the measured one. See docs/CLOSING-THE-LOOP.md.
// The options are declared here; the work is tools/replay/replay_command.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "common/cli/command_line.hpp"
#include "common/cli/exit_code.hpp"
#include "record/csv.hpp"
#include "tools/replay/replay_command.hpp"

namespace {

using namespace mrd::tools;
using Arguments = ReplayArguments;

void add_options(CLI::App& app, Arguments& a) {
  app.add_option(
         "run", a.run_path,
         "the run: the project's CSV (header names units), a foreign delimited file or MATLAB .mat "
         "file with --columns, or a candump -l log")
      ->required();
  a.run_options.add_to(app);
  app.add_flag("--recorded-velocity", a.replay_options.use_recorded_velocity,
               "feed the run's velocity to the observer instead of the controller's filter");
  app.add_option(
      "--zero-phase-velocity", a.zero_phase_cutoff,
      "offline: the velocity from a zero-phase filter of the displacement at this cutoff [Hz] "
      "(0: from the motion's spectrum), as mrd-residual uses, instead of the controller's causal filter")
      ->check(mrd::cli::finite_in(0.0, 1e6));
  app.add_option("--plot", a.plot_dir,
                 "folder for the force-displacement, residual and current PNGs");
  app.add_option("--csv", a.csv_path, "write the per-sample replay as CSV");
  app.add_option("--report", a.report_dir,
                 "write report.html here: the force fit, the residual's structure, the current, provenance "
                 "(docs/CLOSING-THE-LOOP.md)");
  app.add_option("--json", a.json_path, "write the figures as JSON");
  app.add_option("--write-candump", a.candump_path,
                 "also write the run as a candump -l log (LVDT and current feedback frames; "
                 "canplayer can send it onto a bus)");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Replay a recorded damper run through the controller's observer and compensator"};
  mrd::cli::set_up(app, "mrd-replay");
  Arguments args;
  add_options(app, args);
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;

  const auto config = args.run_options.load_config();
  if (!config) return mrd::cli::kUsage;
  if (!mrd::cli::check_outputs("mrd-replay", {&args.csv_path, &args.json_path, &args.candump_path},
                               {&args.plot_dir, &args.report_dir})) {
    return mrd::cli::kIo;
  }
  try {
    return run_replay_command(args, *config, argc, argv);
  } catch (const mrd::record::InputError& e) {
    std::fprintf(stderr, "mrd-replay: %s\n", e.what());
    return mrd::cli::kBadInput;
  }
}
