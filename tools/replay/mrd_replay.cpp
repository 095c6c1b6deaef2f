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

// The command line, as parsed.
struct Arguments {
  std::string run_path, plot_dir, csv_path, json_path, candump_path, report_dir;
  ReplayOptions replay_options;
  RunOptionsCli run_options;
  double zero_phase = 0.0;
  CLI::Option* zero_phase_option = nullptr;
};

void add_options(CLI::App& app, Arguments& a) {
  app.add_option(
         "run", a.run_path,
         "the run: the project's CSV (header names units), a foreign delimited file or MATLAB .mat "
         "file with --columns, or a candump -l log")
      ->required();
  a.run_options.add_to(app);
  app.add_flag("--recorded-velocity", a.replay_options.use_recorded_velocity,
               "feed the run's velocity to the observer instead of the controller's filter");
  a.zero_phase_option = app.add_option(
      "--zero-phase-velocity", a.zero_phase,
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

// The replay and how long it took; the context points into it.
struct TimedReplay {
  ReplayResult result;
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;
};

TimedReplay timed_replay(const mrd::record::RecordedRun& run, const ReplayOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = thread_cpu_seconds();
  TimedReplay timed{replay(run, options)};
  timed.cpu_seconds = thread_cpu_seconds() - cpu_start;
  timed.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return timed;
}

// Every output asked for after the summary, each tried whatever the others did; kIo when one failed.
int write_outputs(const Arguments& a, const ReplayContext& context, int argc, char** argv) {
  int status = mrd::cli::kOk;
  if (!a.json_path.empty()) {
    if (const std::string why = mrd::record::write_text_file(a.json_path, replay_json(context)); !why.empty()) {
      std::fprintf(stderr, "mrd-replay: %s\n", why.c_str());
      status = mrd::cli::kIo;
    }
  }
  if (!a.csv_path.empty()) {
    if (const auto why = write_replay_csv(context, a.csv_path); !why.empty()) {
      std::fprintf(stderr, "mrd-replay: %s\n", why.c_str());
      status = mrd::cli::kIo;
    }
  }
  if (!a.plot_dir.empty()) {
    if (const auto why = plot_replay(context, a.plot_dir); !why.empty()) {
      std::fprintf(stderr, "mrd-replay: plot skipped: %s\n", why.c_str());
    }
  }
  if (!a.report_dir.empty()) {
    std::vector<std::string> inputs = {a.run_path};
    if (!a.run_options.config_path().empty()) inputs.push_back(a.run_options.config_path());
    if (const auto why = write_replay_report(context, provenance_of("mrd-replay", argc, argv, inputs), a.report_dir);
        !why.empty()) {
      std::fprintf(stderr, "mrd-replay: report: %s\n", why.c_str());
      status = mrd::cli::kIo;
    }
  }
  return status;
}

// Reads the run, replays it, prints the summary and writes the outputs. Throws InputError for a
// run or a column mapping that cannot be read.
int replay_run(const Arguments& a, const mrd::config::LoadedConfig& config, int argc, char** argv) {
  ReplayOptions options = a.replay_options;
  options.law = config.config.law;
  const mrd::record::RunReadOptions read = a.run_options.read_options(config);
  options.amps_per_volt = a.run_options.amps_per_volt();
  if (a.zero_phase_option->count() > 0) options.zero_phase_cutoff = a.zero_phase;

  const mrd::record::RecordedRun run = mrd::record::read_recorded_run(a.run_path, read);
  if (!a.candump_path.empty()) {
    const std::string why =
        mrd::record::write_text_file(a.candump_path, mrd::record::format_candump(run, options.amps_per_volt, read.can));
    if (!why.empty()) {
      std::fprintf(stderr, "mrd-replay: %s\n", why.c_str());
      return mrd::cli::kIo;
    }
  }
  const TimedReplay timed = timed_replay(run, options);
  const ReplayContext context{run, options, timed.result, timed.wall_seconds, timed.cpu_seconds};
  std::fputs(replay_summary(context).c_str(), stdout);
  return write_outputs(a, context, argc, argv);
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
    return replay_run(args, *config, argc, argv);
  } catch (const mrd::record::InputError& e) {
    std::fprintf(stderr, "mrd-replay: %s\n", e.what());
    return mrd::cli::kBadInput;
  }
}
