// mrd-replay: runs the firmware's control law (schedule, J-A + Bingham observer, hysteresis
// compensator) over a recorded run, sample by sample, and compares the observer's force with
// the measured one. See docs/CLOSING-THE-LOOP.md.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>

#include "firmware/config_loader.hpp"
#include "tools/csv.hpp"
#include "tools/replay/candump_log.hpp"
#include "tools/replay/replay.hpp"
#include "tools/replay/replay_report.hpp"
#include "tools/replay/run_reader.hpp"

namespace {

using namespace mrd::tools;

// CPU time of this thread: the replay's own work, whatever else the machine runs.
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

bool write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Replay a recorded damper run through the controller's observer and compensator"};
  std::string run_path, columns_text, config_path, plot_dir, csv_path, json_path, candump_path;
  double current = 0.0, sample_rate = 0.0, amps_per_volt = 0.0;
  RunReadOptions read;
  ReplayOptions replay_options;
  app.add_option(
         "run", run_path,
         "the run: the project's CSV (header names units), a foreign CSV with --columns, or a "
         "candump -l log")
      ->required();
  app.add_option("--columns", columns_text,
                 "map a foreign file's columns: t=time_s,D=displacement_cm,... by header name, or "
                 "1=time_s,2=displacement_mm,... by position (no header); units: " +
                     known_unit_names());
  auto* current_option =
      app.add_option("--current", current, "constant coil current of the run [A]");
  auto* from_name =
      app.add_flag("--current-from-name", read.current_from_name,
                   "read the constant current from the file name (25mm0x25Hz0x5A.txt: 0.5 A)");
  current_option->excludes(from_name);
  auto* rate_option =
      app.add_option("--sample-rate", sample_rate, "[Hz], for files without a time column");
  app.add_option("--config", config_path,
                 "the controller's TOML config (default: the embedded one)");
  auto* gain_option =
      app.add_option("--amps-per-volt", amps_per_volt,
                     "current driver gain [A/V], for runs that logged its command voltage");
  app.add_flag("--recorded-velocity", replay_options.use_recorded_velocity,
               "feed the run's velocity to the observer instead of the controller's filter");
  double zero_phase = 0.0;
  auto* zero_phase_option = app.add_option(
      "--zero-phase-velocity", zero_phase,
      "offline: the velocity from a zero-phase filter of the displacement at this cutoff [Hz] "
      "(0: from the motion's spectrum), as mrd-residual uses, instead of the controller's causal filter");
  app.add_option("--plot", plot_dir,
                 "write the force-displacement, residual and current PNGs here");
  app.add_option("--csv", csv_path, "write the per-sample replay as CSV");
  app.add_option("--json", json_path, "write the figures as JSON");
  app.add_option("--write-candump", candump_path,
                 "also write the run as a candump -l log (LVDT and current feedback frames; "
                 "canplayer can send it onto a bus)");
  CLI11_PARSE(app, argc, argv);

  const auto config = config_path.empty() ? mrd::firmware::load_default_config()
                                          : mrd::firmware::load_config_file(config_path);
  if (!config.ok()) {
    std::fprintf(stderr, "%s", config.report().c_str());
    return 1;
  }
  for (const auto& warning : config.warnings)
    std::fprintf(stderr, "%s\n", warning.to_string().c_str());
  replay_options.law = config.config.law;
  read.can = config.config.can;
  try {
    if (!columns_text.empty()) read.columns = parse_column_mapping(columns_text);
    if (current_option->count() > 0) read.current = current;
    if (rate_option->count() > 0) read.sample_rate = sample_rate;
    if (gain_option->count() > 0) replay_options.amps_per_volt = amps_per_volt;
    if (zero_phase_option->count() > 0) replay_options.zero_phase_cutoff = zero_phase;

    const RecordedRun run = read_recorded_run(run_path, read);
    if (!candump_path.empty() &&
        !write_file(candump_path, format_candump(run, replay_options.amps_per_volt, read.can))) {
      std::fprintf(stderr, "mrd-replay: cannot write %s\n", candump_path.c_str());
      return 1;
    }
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_seconds();
    const ReplayResult result = replay(run, replay_options);
    const double cpu = thread_cpu_seconds() - cpu_start;
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
    const ReplayContext context{run, replay_options, result, wall.count(), cpu};

    std::fputs(replay_summary(context).c_str(), stdout);
    int status = 0;
    if (!json_path.empty() && !write_file(json_path, replay_json(context))) {
      std::fprintf(stderr, "mrd-replay: cannot write %s\n", json_path.c_str());
      status = 1;
    }
    if (!csv_path.empty()) {
      if (const auto why = write_replay_csv(context, csv_path); !why.empty()) {
        std::fprintf(stderr, "mrd-replay: %s\n", why.c_str());
        status = 1;
      }
    }
    if (!plot_dir.empty()) {
      if (const auto why = plot_replay(context, plot_dir); !why.empty()) {
        std::fprintf(stderr, "mrd-replay: plot skipped: %s\n", why.c_str());
      }
    }
    return status;
  } catch (const InputError& e) {
    std::fprintf(stderr, "mrd-replay: %s\n", e.what());
    return 2;
  }
}
