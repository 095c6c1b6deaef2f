#include "tools/hil/hil_report.hpp"

#include <cstdio>
#include <fstream>
#include <string>

#include "common/cli/exit_code.hpp"
#include "record/csv.hpp"
#include "record/row_screen.hpp"
#include "record/run_reader.hpp"
#include "tools/hil/force_join.hpp"
#include "tools/hil/telemetry_csv.hpp"
#include "tools/plot/gnuplot.hpp"

namespace mrd::tools {

namespace {

// The paper's Fig. 14: the plant's true force (the measurement a test rig would give) over the
// observer's. `data`: force_displacement.csv.
plot::Figure force_displacement_figure(const std::string& data, const std::string& png) {
  return {.output = png,
          .title = "mrd-controller against mrd-plant: force against displacement",
          .width = 1000,
          .height = 700,
          .panels = {{.x = {"displacement", "mm"},
                      .y = {"force", "kN"},
                      .data = {data, true},
                      .series = {{"controller observer", plot::column(1), plot::column(3).times(1e-3),
                                  plot::lines(plot::colour::kBlue, 2.0)},
                                 {"plant (true force)", plot::column(1), plot::column(2).times(1e-3),
                                  plot::lines(plot::colour::kDarkGrey), plot::Layer::measured}}}}};
}

// What the reader set aside, each row with its line (the first kMaxListed of each file).
constexpr std::size_t kMaxListed = 10;

void print_set_aside(const TelemetryLog& log) {
  const std::string counts = mrd::record::set_aside_counts(log.set_aside_rows, "line");
  if (counts.empty()) return;
  std::printf("telemetry rows set aside: %s\n", counts.c_str());
  for (std::size_t i = 0; i < log.set_aside_rows.size() && i < kMaxListed; ++i) {
    const auto& r = log.set_aside_rows[i];
    std::printf("  line %zu: %.*s%s\n", r.line, static_cast<int>(r.reason.size()), r.reason.data(),
                r.column.empty() ? "" : (", column '" + r.column + "'").c_str());
  }
  if (log.set_aside_rows.size() > kMaxListed) std::printf("  ... and %zu more\n", log.set_aside_rows.size() - kMaxListed);
}

// Gaps with records missing one a line; steps of a late loop (no record missing) in one line.
void print_gaps(const TelemetryLog& log) {
  std::size_t missing = 0, late = 0;
  const TelemetryGap* longest_late = nullptr;
  for (const auto& g : log.gaps) {
    if (g.missing == 0) {
      ++late;
      if (longest_late == nullptr || g.duration() > longest_late->duration()) longest_late = &g;
    } else if (missing++ == 0) {
      std::printf("telemetry gaps (records missing; no figure spans one, a transition across one is dated by it):\n");
    }
    if (g.missing > 0 && missing <= kMaxListed) std::printf("  %s\n", to_string(g, log.rows).c_str());
  }
  if (missing > kMaxListed) std::printf("  ... and %zu more\n", missing - kMaxListed);
  if (late > 0) {
    std::printf("telemetry: %zu steps over 1.5 periods with no record missing (the loop ran late); the longest "
                "%.3f s from %.3f s (line %zu)\n",
                late, longest_late->duration(), longest_late->start, log.rows[longest_late->before + 1].line);
  }
}

void print_plant_log(const mrd::record::RecordedRun& plant, const ForceJoin& j) {
  for (const auto& note : plant.notes) std::printf("plant log: %s\n", note.c_str());
  if (j.plant_gaps.empty()) return;
  std::printf("plant log gaps: %zu; %zu records in control fall in them and are left out of the force error\n",
              j.plant_gaps.size(), j.in_plant_gaps);
  for (std::size_t i = 0; i < j.plant_gaps.size() && i < kMaxListed; ++i)
    std::printf("  %.3f s from %.3f s\n", j.plant_gaps[i].second - j.plant_gaps[i].first, j.plant_gaps[i].first);
  if (j.plant_gaps.size() > kMaxListed) std::printf("  ... and %zu more\n", j.plant_gaps.size() - kMaxListed);
}

}  // namespace

int print_hil_report(const HilReportOptions& options) {
  try {
    const auto log = read_telemetry_csv(options.telemetry_path);
    const auto& telemetry = log.rows;
    const auto plant = mrd::record::read_recorded_run(options.plant_path);
    // Files written before the time-origin line need the origins from the command line.
    const auto origin = [](const std::optional<double>& given, const std::optional<double>& in_file,
                           const std::string& file, const char* option) {
      if (given) return *given;
      if (in_file) return *in_file;
      throw mrd::record::InputError(file + ": no time-origin line ('# time_s 0 is CLOCK_MONOTONIC ...'); give " +
                                    option + " (the program printed it)");
    };
    const double offset = origin(options.controller_t0, log.time_origin, options.telemetry_path, "--controller-t0") -
                          origin(options.plant_t0, plant.time_origin, options.plant_path, "--plant-t0");
    std::printf("telemetry: %zu records at %.0f Hz; plant log: %zu samples at %.0f Hz\n", telemetry.size(),
                log.record_rate, plant.size(), plant.sample_rate);
    print_set_aside(log);
    print_gaps(log);
    std::printf("supervisor transitions:\n");
    for (const auto& c : state_changes(telemetry, log.gaps)) std::printf("  %s\n", to_string(c).c_str());
    const auto j = join_force(telemetry, plant, offset);
    print_plant_log(plant, j);

    std::printf("joined %zu records in control; LVDT transport lag %.2f ms (displacement RMS "
                "difference %.1f um after it)\n",
                j.rows, j.lag * 1e3, j.displacement_rms * 1e6);
    std::printf("observer force error against the plant's true force: RMS %.3f kN, max %.3f kN, "
                "peak force %.2f kN, NRMSE %.2f %%\n",
                j.rms_error * 1e-3, j.max_error * 1e-3, j.peak_force * 1e-3, 100.0 * j.nrmse());
    if (!options.plot_dir.empty()) {
      const std::string data = options.plot_dir + "/force_displacement.csv";
      const std::string png = options.plot_dir + "/force_displacement.png";
      std::ofstream out(data);
      // A blank line ends a stretch: gnuplot draws no line across a gap or a row left out.
      // The column line as pandas.read_csv(f) reads it (blank lines skipped), forces in N.
      out << "displacement_mm,true_force_N,observer_force_N\n";
      const double long_step = 1.5 / log.record_rate;
      for (std::size_t i = 0; i < j.rows; ++i) {
        if (i > 0 && j.time[i] - j.time[i - 1] > long_step) out << '\n';
        out << j.displacement[i] * 1e3 << ',' << j.true_force[i] << ',' << j.observer_force[i] << '\n';
      }
      out.close();
      if (!out) {
        std::fprintf(stderr, "mrd-hil-report: cannot write %s\n", data.c_str());
        return mrd::cli::kIo;
      }
      const std::string error = plot::draw({force_displacement_figure(data, png)});
      if (error.empty()) {
        std::printf("plot: %s (data %s)\n", png.c_str(), data.c_str());
      } else {
        std::fprintf(stderr, "mrd-hil-report: no plot: %s\n", error.c_str());
      }
    }
  } catch (const mrd::record::InputError& e) {
    std::fprintf(stderr, "mrd-hil-report: %s\n", e.what());
    return mrd::cli::kBadInput;
  }
  return mrd::cli::kOk;
}

}  // namespace mrd::tools
