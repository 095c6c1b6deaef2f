// mrd-replay: runs the firmware's control law (schedule, J-A + Bingham observer, hysteresis
// compensator) over a recorded run, sample by sample, and compares the observer's force with
// the measured one. See docs/CLOSING-THE-LOOP.md.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <ctime>

#include "common/cli/command_line.hpp"
#include "config/config_loader.hpp"
#include "record/csv.hpp"
#include "record/candump_log.hpp"
#include "tools/replay/replay.hpp"
#include "tools/replay/replay_report.hpp"
#include "tools/replay/run_options_cli.hpp"
#include "record/run_reader.hpp"

namespace {

using namespace mrd::tools;

// CPU time of this thread: the replay's own work, whatever else the machine runs.
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Replay a recorded damper run through the controller's observer and compensator"};
  mrd::cli::set_up(app, "mrd-replay");
  std::string run_path, plot_dir, csv_path, json_path, candump_path, report_dir;
  ReplayOptions replay_options;
  app.add_option(
         "run", run_path,
         "the run: the project's CSV (header names units), a foreign delimited file or MATLAB .mat "
         "file with --columns, or a candump -l log")
      ->required();
  RunOptionsCli run_options;
  run_options.add_to(app);
  app.add_flag("--recorded-velocity", replay_options.use_recorded_velocity,
               "feed the run's velocity to the observer instead of the controller's filter");
  double zero_phase = 0.0;
  auto* zero_phase_option = app.add_option(
      "--zero-phase-velocity", zero_phase,
      "offline: the velocity from a zero-phase filter of the displacement at this cutoff [Hz] "
      "(0: from the motion's spectrum), as mrd-residual uses, instead of the controller's causal filter")
      ->check(mrd::cli::finite_in(0.0, 1e6));
  app.add_option("--plot", plot_dir,
                 "folder for the force-displacement, residual and current PNGs");
  app.add_option("--csv", csv_path, "write the per-sample replay as CSV");
  app.add_option("--report", report_dir,
                 "write report.html here: the force fit, the residual's structure, the current, provenance "
                 "(docs/CLOSING-THE-LOOP.md)");
  app.add_option("--json", json_path, "write the figures as JSON");
  app.add_option("--write-candump", candump_path,
                 "also write the run as a candump -l log (LVDT and current feedback frames; "
                 "canplayer can send it onto a bus)");
  if (const auto status = mrd::cli::parse(app, argc, argv)) return *status;

  const auto config = run_options.load_config();
  if (!config) return mrd::cli::kUsage;
  if (!mrd::cli::check_outputs("mrd-replay", {&csv_path, &json_path, &candump_path}, {&plot_dir, &report_dir})) {
    return mrd::cli::kIo;
  }
  replay_options.law = config->config.law;
  try {
    const mrd::record::RunReadOptions read = run_options.read_options(*config);
    replay_options.amps_per_volt = run_options.amps_per_volt();
    if (zero_phase_option->count() > 0) replay_options.zero_phase_cutoff = zero_phase;

    const mrd::record::RecordedRun run = mrd::record::read_recorded_run(run_path, read);
    if (!candump_path.empty() &&
        !mrd::record::write_text_file(candump_path, mrd::record::format_candump(run, replay_options.amps_per_volt, read.can))) {
      std::fprintf(stderr, "mrd-replay: cannot write %s\n", candump_path.c_str());
      return mrd::cli::kIo;
    }
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_seconds();
    const ReplayResult result = replay(run, replay_options);
    const double cpu = thread_cpu_seconds() - cpu_start;
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
    const ReplayContext context{run, replay_options, result, wall.count(), cpu};

    std::fputs(replay_summary(context).c_str(), stdout);
    int status = 0;
    if (!json_path.empty() && !mrd::record::write_text_file(json_path, replay_json(context))) {
      std::fprintf(stderr, "mrd-replay: cannot write %s\n", json_path.c_str());
      status = mrd::cli::kIo;
    }
    if (!csv_path.empty()) {
      if (const auto why = write_replay_csv(context, csv_path); !why.empty()) {
        std::fprintf(stderr, "mrd-replay: %s\n", why.c_str());
        status = mrd::cli::kIo;
      }
    }
    if (!plot_dir.empty()) {
      if (const auto why = plot_replay(context, plot_dir); !why.empty()) {
        std::fprintf(stderr, "mrd-replay: plot skipped: %s\n", why.c_str());
      }
    }
    if (!report_dir.empty()) {
      std::vector<std::string> inputs = {run_path};
      if (!run_options.config_path().empty()) inputs.push_back(run_options.config_path());
      if (const auto why = write_replay_report(context, provenance_of("mrd-replay", argc, argv, inputs), report_dir);
          !why.empty()) {
        std::fprintf(stderr, "mrd-replay: report: %s\n", why.c_str());
        status = 3;
      }
    }
    return status;
  } catch (const mrd::record::InputError& e) {
    std::fprintf(stderr, "mrd-replay: %s\n", e.what());
    return mrd::cli::kBadInput;
  }
}
