#include "tools/replay/replay_command.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>

#include "common/cli/exit_code.hpp"
#include "record/candump_log.hpp"
#include "record/csv.hpp"
#include "record/run_reader.hpp"
#include "tools/replay/replay_report.hpp"

namespace mrd::tools {

namespace {

using Arguments = ReplayArguments;

// CPU time of this thread: the replay's own work, whatever else the machine runs.
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
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

}  // namespace

int run_replay_command(const ReplayArguments& a, const mrd::config::LoadedConfig& config, int argc, char** argv) {
  ReplayOptions options = a.replay_options;
  options.law = config.config.law;
  const mrd::record::RunReadOptions read = a.run_options.read_options(config);
  options.amps_per_volt = a.run_options.amps_per_volt();
  if (a.zero_phase_cutoff) options.zero_phase_cutoff = *a.zero_phase_cutoff;

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

}  // namespace mrd::tools
