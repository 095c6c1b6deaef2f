#include "tools/replay/replay_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tools/gnuplot.hpp"
#include "tools/json.hpp"
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
        "NRMSE %.4g (RMS / measured range %.4g N)\n",
        f->rms, f->max, f->mean, f->nrmse, f->measured_range);
  } else {
    out += "force error: the run has no measured force\n";
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
  std::ostringstream out;
  out << "{\n  \"run\": " << json_string(run.name) << ",\n"
      << "  \"samples\": " << run.size() << ",\n"
      << "  \"duration_s\": " << json_number(run.duration()) << ",\n"
      << "  \"sample_rate_Hz\": " << json_number(run.sample_rate) << ",\n"
      << "  \"sampling\": {\"min_period_s\": " << json_number(s.min_period)
      << ", \"max_period_s\": " << json_number(s.max_period) << ", \"gaps\": " << s.gaps << "},\n"
      << "  \"coil_signal\": " << json_string(to_string(run.coil_signal)) << ",\n"
      << "  \"coil_source\": " << json_string(run.coil_source) << ",\n"
      << "  \"amps_per_volt\": "
      << (c.options.amps_per_volt ? json_number(*c.options.amps_per_volt) : "null") << ",\n"
      << "  \"velocity\": " << json_string(c.options.use_recorded_velocity ? "recorded" : "filter")
      << ",\n"
      << "  \"force\": ";
  if (const auto& f = c.result.force) {
    out << "{\"rms_N\": " << json_number(f->rms) << ", \"max_N\": " << json_number(f->max)
        << ", \"mean_N\": " << json_number(f->mean)
        << ", \"measured_range_N\": " << json_number(f->measured_range)
        << ", \"nrmse\": " << json_number(f->nrmse) << "}";
  } else {
    out << "null";
  }
  const Range predicted = range_of(c.result.trace.predicted_force);
  const Range command = range_of(c.result.trace.command_current);
  out << ",\n  \"predicted_force_N\": {\"min\": " << json_number(predicted.min)
      << ", \"max\": " << json_number(predicted.max) << "},\n"
      << "  \"command_current_A\": {\"min\": " << json_number(command.min)
      << ", \"max\": " << json_number(command.max) << ", \"mean\": " << json_number(command.mean)
      << "},\n  \"notes\": [";
  for (std::size_t i = 0; i < run.notes.size(); ++i)
    out << (i ? ", " : "") << json_string(run.notes[i]);
  out << "],\n  \"wall_s\": " << json_number(c.wall_seconds)
      << ",\n  \"cpu_s\": " << json_number(c.cpu_seconds)
      << ",\n  \"real_time_factor\": " << json_number(real_time_factor(c, c.wall_seconds))
      << ",\n  \"real_time_factor_cpu\": " << json_number(real_time_factor(c, c.cpu_seconds))
      << "\n}\n";
  return out.str();
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
  std::ostringstream gp;
  gp << "set terminal pngcairo size 900,650\nset grid\nset key left top\n"
     << "set output '" << png("replay_force_displacement.png") << "'\n"
     << "set title '" << name << ": force against displacement" << error << "' noenhanced\n"
     << "set xlabel 'displacement [mm]'\nset ylabel 'force [N]'\n"
     << "plot "
     << (force ? "'" + data +
                     "' using 2:3 with points pt 7 ps 0.25 lc rgb '#888888' title 'measured', "
               : "")
     << "'" << data
     << "' using 2:4 with points pt 7 ps 0.25 lc rgb '#d62728' title 'predicted (observer)'\n";
  if (force) {
    gp << "set output '" << png("replay_residual.png") << "'\n"
       << "set title '" << name << ": residual, measured - predicted" << error << "' noenhanced\n"
       << "set xlabel 'time [s]'\nset ylabel 'residual [N]'\n"
       << "plot '" << data
       << "' using 1:5 with lines lw 1 lc rgb '#1f77b4' title 'measured - predicted'\n";
  }
  gp << "set output '" << png("replay_current.png") << "'\n"
     << "set title '" << name
     << ": coil current of the run, and the command the controller would have given' noenhanced\n"
     << "set xlabel 'time [s]'\nset ylabel 'current [A]'\n"
     << "plot '" << data << "' using 1:6 with lines lw 1 title 'run (drives the observer)', '"
     << data << "' using 1:7 with lines lw 1 title 'controller command'\n";
  return run_gnuplot(gp.str());
}

}  // namespace mrd::tools
