#include "tools/table4/table4_report.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <utility>

#include "common/cli/exit_code.hpp"
#include "tools/plot/gnuplot.hpp"

namespace mrd::tools {

namespace {

bool write_trace(const std::string& path, const Table4RunResult& off, const Table4RunResult& on) {
  std::ofstream out(path);
  // 9 significant digits, as mrd-replay --csv: the stream's default 6 gave two rows the same time
  // past 10 s at a control rate above 10 kHz (past 1000 s at 1 kHz); check_csv_outputs.py refuses that.
  out.precision(9);
  out << "time_s,displacement_mm,scheduled_current_A,command_current_A,target_B_T,B_T,force_N,"
         "intended_force_N,observer_force_N,compensated_command_A,compensated_B_T,"
         "compensated_force_N\n";
  for (std::size_t i = 0; i < off.trace.size(); ++i) {
    const auto& a = off.trace[i];
    const auto& b = on.trace[i];
    out << a.time << ',' << a.displacement * 1e3 << ',' << a.scheduled_current << ','
        << a.command_current << ',' << a.target_B << ',' << a.B << ',' << a.force << ','
        << a.intended_force << ',' << b.observer_force << ',' << b.command_current
        << ',' << b.B << ',' << b.force << '\n';
  }
  out.close();
  return static_cast<bool>(out);
}

// The paper's Figure 14 (force against displacement, after the first cycle) over B against time.
// Columns of table4_run.csv: 1 time, 2 displacement, 5 intended B, 6 B, 7 force, 8 intended
// force, 11 and 12 the compensated run's B and force; forces in N, drawn in kN.
plot::Figure table4_figure(const std::string& csv, const std::string& png, double first_cycle_s) {
  namespace plot = plot;
  const auto after_first_cycle = plot::column(2).where(1, first_cycle_s);
  const auto in_kN = [](int index) { return plot::column(index).times(1e-3); };
  return {.output = png,
          .title = "Simulated Table 4 run (after the first cycle)",
          .width = 1100,
          .height = 800,
          .panels = {{.x = {"displacement", "mm"},
                      .y = {"force", "kN"},
                      .data = {csv, true},
                      .series = {{"intended (no hysteresis)", after_first_cycle, in_kN(8), plot::lines(plot::colour::kGrey, 2.0)},
                                 {"damper, uncompensated", after_first_cycle, in_kN(7), plot::lines(plot::colour::kRed)},
                                 {"damper, compensated", after_first_cycle, in_kN(12), plot::lines(plot::colour::kBlue)}}},
                     {.x = {"time", "s"},
                      .y = {"B", "T"},
                      .data = {csv, true},
                      .series = {{"intended B", plot::column(1), plot::column(5), plot::lines(plot::colour::kGrey, 2.0)},
                                 {"uncompensated", plot::column(1), plot::column(6), plot::lines(plot::colour::kRed)},
                                 {"compensated", plot::column(1), plot::column(11), plot::lines(plot::colour::kBlue)}}}}};
}

}  // namespace

int report_table4_comparison(Table4RunOptions options, const std::string& out_dir, bool draw_plot) {
  options.controller.compensate_hysteresis = false;
  const Table4RunResult off = run_table4(options);
  options.controller.compensate_hysteresis = true;
  const Table4RunResult on = run_table4(options);

  std::printf("mrd: simulated Table 4 run, %.3g Hz, +-%.3g mm, %.0f Hz control, %d cycles, "
              "LVDT noise %.3g um RMS\n",
              options.profile.frequency, options.profile.amplitude * 1e3,
              1.0 / options.controller.observer.sample_period, options.cycles, options.lvdt_noise_rms * 1e6);
  std::printf("figures over cycles 2..%d; peak damper force %.1f kN\n\n", options.cycles,
              on.peak_force * 1e-3);
  std::printf("%-24s %22s %26s %26s\n", "", "B - intended B [T]", "force - intended [kN]",
              "observer force error [kN]");
  std::printf("%-24s %22s %26s %26s\n", "", "RMS / max", "RMS / max", "RMS / max");
  for (const auto& [name, r] : {std::pair{"without compensation", &off}, std::pair{"with compensation", &on}}) {
    std::printf("%-24s %10.4f / %-9.4f %12.3f / %-11.3f %12.3f / %-11.3f\n", name,
                r->B_tracking.rms, r->B_tracking.max, r->force_vs_intended.rms * 1e-3,
                r->force_vs_intended.max * 1e-3, r->observer_force.rms * 1e-3,
                r->observer_force.max * 1e-3);
  }

  const std::string csv = out_dir + "/table4_run.csv";
  if (!write_trace(csv, off, on)) {
    std::fprintf(stderr, "mrd-table4-run: cannot write %s: %s\n", csv.c_str(), std::strerror(errno));
    return mrd::cli::kIo;
  }
  std::printf("\nwrote %s\n", csv.c_str());
  if (draw_plot) {
    const std::string png = out_dir + "/table4_force_displacement.png";
    const std::string error = plot::draw({table4_figure(csv, png, 1.0 / options.profile.frequency)});
    if (error.empty()) {
      std::printf("wrote %s\n", png.c_str());
    } else {
      std::fprintf(stderr, "mrd-table4-run: no plot: %s\n", error.c_str());
    }
  }
  return mrd::cli::kOk;
}

}  // namespace mrd::tools
