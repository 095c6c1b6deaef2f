#include "tools/replay/replay_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "tools/plot/gnuplot.hpp"
#include "tools/json.hpp"
#include "tools/report/fit_statistics.hpp"
#include "tools/report/force_fit.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace {

struct Range {
  double min = 0.0, max = 0.0, mean = 0.0;
};
Range range_of(const std::vector<double>& v) {
  if (v.empty()) return {};
  Range r{v[0], v[0], 0.0};
  double sum = 0.0;
  for (const double x : v) {
    r.min = std::min(r.min, x);
    r.max = std::max(r.max, x);
    sum += x;
  }
  r.mean = sum / static_cast<double>(v.size());
  return r;
}

double real_time_factor(const ReplayContext& c, double seconds) {
  return seconds > 0.0 ? c.run.duration() / seconds : 0.0;
}

std::string velocity_source(const ReplayContext& c) {
  if (c.options.use_recorded_velocity) return "recorded";
  if (c.options.zero_phase_cutoff) return "offline zero-phase filter of the displacement";
  return format("the controller's filter (%g Hz)", c.options.law.observer.velocity_cutoff_frequency);
}

std::string coil_description(const ReplayContext& c) {
  std::string out = std::string(to_string(c.run.coil_signal)) + " from " + c.run.coil_source;
  if (c.run.coil_signal == record::CoilSignal::kCommandVoltage)
    out += format(" x %g A/V", *c.options.amps_per_volt);
  return out;
}

// NRMSE fit [%] of the observer's force to the measured one.
double replay_fit_percent(const ReplayContext& c) {
  return nrmse_fit_percent(c.run.force, c.result.trace.predicted_force);
}

// The run and its replay as the force-fit section reads them (the run must have force).
ForceFitTraces replay_traces(const ReplayContext& c) {
  ForceFitTraces traces;
  traces.name = std::filesystem::path(c.run.name).filename().string();
  traces.time.resize(c.run.size());
  for (std::size_t i = 0; i < c.run.size(); ++i) traces.time[i] = c.run.time[i] - c.run.time[0];
  traces.displacement = c.run.displacement;
  traces.velocity = c.result.trace.velocity;
  traces.measured = c.run.force;
  traces.predicted = c.result.trace.predicted_force;
  traces.predicted_label = "predicted (observer)";
  return traces;
}

// A replay worse than the measured mean is almost always a config made for another damper: say
// so, and how to get this one's. "" when the fit is not that bad or there is no force.
std::string unfitted_hint(const ReplayContext& c) {
  if (!c.result.force) return {};
  const double fit = replay_fit_percent(c);
  if (!(fit < 0.0)) return {};
  const Range predicted = range_of(c.result.trace.predicted_force);
  const Range measured = range_of(c.run.force);
  const double ratio = (predicted.max - predicted.min) / std::max(measured.max - measured.min, 1e-300);
  return format("hint: the config's damper predicts this run worse than the measured mean force (fit %.0f %%; its force "
                "range is %.3g times the measured one), so it is not a model of this damper. Identify this one with "
                "`mrd-residual RUN --write-config damper.toml` and replay with `--config damper.toml`.",
                fit, ratio);
}

}  // namespace

std::string replay_summary(const ReplayContext& c) {
  const auto& run = c.run;
  const auto& s = c.result.sampling;
  std::string out = format("%s: %zu samples, %.6g s at %.6g Hz (periods %.4g..%.4g ms, %zu gaps)\n",
                           run.name.c_str(), run.size(), run.duration(), run.sample_rate,
                           1e3 * s.min_period, 1e3 * s.max_period, s.gaps);
  out += "coil: " + coil_description(c) + "; velocity: " + velocity_source(c) + "\n";
  for (const auto& note : run.notes) out += "note: " + note + "\n";
  if (const auto& f = c.result.force) {
    out += format(
        "force error (measured - predicted): RMS %.4g N, max %.4g N, mean %.4g N; "
        "NRMSE %.4g (RMS / measured range %.4g N); fit %.2f %%\n",
        f->rms, f->max, f->mean, f->nrmse, f->measured_range, replay_fit_percent(c));
    if (const std::string hint = unfitted_hint(c); !hint.empty()) out += hint + "\n";
  } else {
    out += "force: none measured in this run, so no force error\n";
  }
  const Range predicted = range_of(c.result.trace.predicted_force);
  const Range command = range_of(c.result.trace.command_current);
  out += format("predicted force %.4g..%.4g N; commanded current %.4g..%.4g A (mean %.4g A)\n",
                predicted.min, predicted.max, command.min, command.max, command.mean);
  out += format("replayed %.6g s of data in %.4g s (%.0fx real time; CPU %.4g s, %.0fx)\n",
                run.duration(), c.wall_seconds, real_time_factor(c, c.wall_seconds), c.cpu_seconds,
                real_time_factor(c, c.cpu_seconds));
  return out;
}

std::string replay_json(const ReplayContext& c) {
  const auto& run = c.run;
  const auto& s = c.result.sampling;
  Json force = nullptr;
  if (const auto& f = c.result.force) {
    force = {{"rms_N", f->rms}, {"max_N", f->max}, {"mean_N", f->mean}, {"measured_range_N", f->measured_range},
             {"nrmse", f->nrmse}, {"fit_percent", replay_fit_percent(c)}};
  }
  const Range predicted = range_of(c.result.trace.predicted_force);
  const Range command = range_of(c.result.trace.command_current);
  const Json fit = run.has_force() ? force_fit_json(force_fit_figures(replay_traces(c))) : Json(nullptr);
  return json_text({{"run", run.name},
                    {"samples", run.size()},
                    {"duration_s", run.duration()},
                    {"sample_rate_Hz", run.sample_rate},
                    {"sampling", {{"min_period_s", s.min_period}, {"max_period_s", s.max_period}, {"gaps", s.gaps}}},
                    {"coil_signal", std::string(to_string(run.coil_signal))},
                    {"coil_source", run.coil_source},
                    {"amps_per_volt", c.options.amps_per_volt ? Json(*c.options.amps_per_volt) : Json(nullptr)},
                    {"velocity", c.options.use_recorded_velocity ? "recorded" : "filter"},
                    {"force", force},
                    {"fit", fit},
                    {"predicted_force_N", {{"min", predicted.min}, {"max", predicted.max}}},
                    {"command_current_A", {{"min", command.min}, {"max", command.max}, {"mean", command.mean}}},
                    {"notes", run.notes},
                    {"wall_s", c.wall_seconds},
                    {"cpu_s", c.cpu_seconds},
                    {"real_time_factor", real_time_factor(c, c.wall_seconds)},
                    {"real_time_factor_cpu", real_time_factor(c, c.cpu_seconds)}});
}

std::string write_replay_csv(const ReplayContext& c, const std::string& path) {
  std::ofstream out(path);
  if (!out) return "cannot write " + path;
  const auto& run = c.run;
  const auto& t = c.result.trace;
  const bool force = run.has_force();
  out << "time_s,displacement_mm,velocity_mm_s,coil_current_A,"
      << (force ? "measured_force_N," : "") << "predicted_force_N," << (force ? "residual_N," : "")
      << "B_T,scheduled_current_A,command_current_A\n";
  char line[512];
  for (std::size_t i = 0; i < run.size(); ++i) {
    int n = std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,", run.time[i],
                          1e3 * run.displacement[i], 1e3 * t.velocity[i], t.coil_current[i]);
    if (force)
      n +=
          std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), "%.9g,", run.force[i]);
    n += std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), "%.9g,",
                       t.predicted_force[i]);
    if (force) {
      n += std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), "%.9g,",
                         run.force[i] - t.predicted_force[i]);
    }
    std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), "%.9g,%.9g,%.9g\n", t.B[i],
                  t.scheduled_current[i], t.command_current[i]);
    out << line;
  }
  return out ? "" : "cannot write " + path;
}

std::string plot_replay(const ReplayContext& c, const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) return "cannot create " + directory + ": " + ec.message();
  const auto& run = c.run;
  const auto& t = c.result.trace;
  const bool force = run.has_force();
  // gnuplot draws 40k points in about a second; longer runs are thinned for the plots only.
  const std::size_t stride = std::max<std::size_t>(1, run.size() / 40000);
  const std::string data = (fs::path(directory) / "replay.dat").string();
  {
    std::ofstream out(data);
    for (std::size_t i = 0; i < run.size(); i += stride) {
      out << run.time[i] - run.time[0] << ' ' << 1e3 * run.displacement[i] << ' '
          << (force ? run.force[i] : NAN) << ' ' << t.predicted_force[i] << ' '
          << (force ? run.force[i] - t.predicted_force[i] : NAN) << ' ' << t.coil_current[i] << ' '
          << t.command_current[i] << '\n';
    }
    if (!out) return "cannot write " + data;
  }
  const std::string name = fs::path(run.name).filename().string();
  const std::string error = c.result.force ? format(", RMS error %.4g N, NRMSE %.3g",
                                                    c.result.force->rms, c.result.force->nrmse)
                                           : "";
  auto png = [&](const char* file) { return (fs::path(directory) / file).string(); };
  plot::Panel force_displacement{.x = {"displacement", "mm"}, .y = {"force", "N"}, .data = {data}};
  force_displacement.series.push_back(
      {"predicted (observer)", plot::column(2), plot::column(4), plot::points(plot::colour::kRed, 0.25)});
  if (force) {
    force_displacement.series.push_back(
        {"measured", plot::column(2), plot::column(3), plot::points(plot::colour::kGrey, 0.25), plot::Layer::measured});
  }
  std::vector<plot::Figure> figures;
  figures.push_back({.output = png("replay_force_displacement.png"),
                     .title = name + ": force against displacement" + error,
                     .panels = {std::move(force_displacement)}});
  if (force) {
    figures.push_back({.output = png("replay_residual.png"),
                       .title = name + ": residual, measured - predicted" + error,
                       .panels = {{.x = {"time", "s"},
                                   .y = {"residual", "N"},
                                   .data = {data},
                                   .series = {{"measured - predicted", plot::column(1), plot::column(5),
                                               plot::lines(plot::colour::kBlue)}}}}});
  }
  figures.push_back({.output = png("replay_current.png"),
                     .title = name + ": coil current of the run, and the command the controller would have given",
                     .panels = {{.x = {"time", "s"},
                                 .y = {"current", "A"},
                                 .data = {data},
                                 .series = {{"run (drives the observer)", plot::column(1), plot::column(6),
                                             plot::lines(plot::colour::kBlue)},
                                            {"controller command", plot::column(1), plot::column(7),
                                             plot::lines(plot::colour::kGreen)}}}}});
  return plot::draw(figures);
}

std::string write_replay_report(const ReplayContext& c, const Provenance& provenance, const std::string& directory) {
  const auto& run = c.run;
  const auto& t = c.result.trace;
  HtmlReport report("mrd-replay: " + run.name, directory);
  report.paragraph(format("The firmware's control law (schedule, J-A + Bingham observer, compensator) run over the "
                          "recorded run sample by sample. Coil: %s; velocity: %s.",
                          coil_description(c).c_str(), velocity_source(c).c_str()));
  std::vector<ReportFigure> run_rows = {{"samples", "samples", static_cast<double>(run.size()), ""},
                                        {"duration", "duration_s", run.duration(), "s"},
                                        {"sample rate", "sample_rate_Hz", run.sample_rate, "Hz"}};
  if (const auto& f = c.result.force) {
    run_rows.push_back({"RMS error", "force.rms_N", f->rms, "N"});
    run_rows.push_back({"max error", "force.max_N", f->max, "N"});
    run_rows.push_back({"NRMSE (RMS / measured range)", "force.nrmse", f->nrmse, ""});
  }
  report.figures("The run and the force error (as the JSON)", run_rows);
  if (const std::string hint = unfitted_hint(c); !hint.empty()) report.paragraph(hint);
  for (const auto& note : run.notes) report.paragraph("note: " + note);
  std::vector<double> time(run.size());
  for (std::size_t i = 0; i < run.size(); ++i) time[i] = run.time[i] - run.time[0];
  if (run.has_force()) {
    add_force_fit(report, replay_traces(c));
  } else {
    report.paragraph("The run has no measured force: only the prediction and the current are shown.");
  }
  report.heading("Coil current");
  report.time_chart({"current", "the run's coil current (drives the observer) and the command the controller would give",
                     "time [s]", "current [A]", &time,
                     {{"run", &t.coil_current, plot::colour::kBlue},
                      {"controller command", &t.command_current, plot::colour::kGreen}},
                     {}});
  report.heading("Damper parameters");
  const model::DamperModel& m = c.options.law.damper;
  report.parameters("From the config (a replay fits nothing, so no standard deviations)",
                    {{"jiles_atherton.Ms", "A/m", m.jiles_atherton.Ms, NAN, "", ""},
                     {"jiles_atherton.a", "A/m", m.jiles_atherton.a, NAN, "", ""},
                     {"jiles_atherton.alpha", "-", m.jiles_atherton.alpha, NAN, "", ""},
                     {"jiles_atherton.k", "A/m", m.jiles_atherton.k, NAN, "", ""},
                     {"jiles_atherton.c", "-", m.jiles_atherton.c, NAN, "", ""},
                     {"fluid.viscosity", "Pa s", m.fluid.viscosity, NAN, "", ""},
                     {"geometry.pole_length", "m", m.geometry.pole_length, NAN, "", ""}});
  report.provenance(provenance);
  return report.write();
}

}  // namespace mrd::tools
