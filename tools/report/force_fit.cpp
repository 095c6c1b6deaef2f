#include "tools/report/force_fit.hpp"

#include <cmath>
#include <limits>

#include "tools/report/fit_statistics.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace {

std::vector<double> kept_residual(const ForceFitTraces& t) {
  std::vector<double> e;
  e.reserve(t.measured.size());
  for (std::size_t i = 0; i < t.measured.size(); ++i)
    if (t.keep.empty() || t.keep[i]) e.push_back(t.measured[i] - t.predicted[i]);
  return e;
}

}  // namespace

ForceFitFigures force_fit_figures(const ForceFitTraces& t, std::size_t lags) {
  ForceFitFigures f;
  f.fit_percent = nrmse_fit_percent(t.measured, t.predicted, t.keep);
  f.baseline_fit_percent = t.baseline.empty() ? std::numeric_limits<double>::quiet_NaN()
                                              : nrmse_fit_percent(t.measured, t.baseline, t.keep);
  const std::vector<double> e = kept_residual(t);
  double sum = 0.0;
  for (const double x : e) {
    sum += x * x;
    f.max_N = std::max(f.max_N, std::abs(x));
  }
  f.rms_N = e.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(e.size()));
  const std::vector<double> r = autocorrelation(e, lags);
  f.lags = r.empty() ? 0 : r.size() - 1;
  f.lag_step_s = t.time.size() > 1 ? (t.time.back() - t.time.front()) / static_cast<double>(t.time.size() - 1) : 0.0;
  f.acf_bound = autocorrelation_bound_95(e.size());
  std::size_t outside = 0;
  for (std::size_t k = 1; k < r.size(); ++k) outside += std::abs(r[k]) > f.acf_bound ? 1 : 0;
  f.acf_outside = f.lags > 0 ? static_cast<double>(outside) / static_cast<double>(f.lags) : 0.0;
  return f;
}

Json force_fit_json(const ForceFitFigures& f) {
  return {{"fit_percent", f.fit_percent},   {"rms_N", f.rms_N},
          {"max_N", f.max_N},               {"baseline_fit_percent", f.baseline_fit_percent},
          {"acf_lags", f.lags},             {"acf_lag_step_s", f.lag_step_s},
          {"acf_bound", f.acf_bound},       {"acf_outside_fraction", f.acf_outside}};
}

void add_autocorrelation_plot(HtmlReport& report, const std::vector<double>& residual, std::size_t lags,
                              double lag_step, const std::string& lag_label, const std::string& caption) {
  const std::vector<double> r = autocorrelation(residual, lags);
  const double bound = autocorrelation_bound_95(residual.size());
  std::vector<double> lag(r.size()), upper(r.size(), bound), lower(r.size(), -bound);
  for (std::size_t k = 0; k < r.size(); ++k) lag[k] = static_cast<double>(k) * lag_step;
  const std::string acf = report.data("autocorrelation", {"lag", "r", "upper_95", "lower_95"}, {&lag, &r, &upper, &lower});
  report.plot("residual_autocorrelation", caption,
              "set xlabel '" + lag_label + "'\nset ylabel 'autocorrelation [-]'\nset yrange [-1:1]\nplot '" + acf +
                  "' using 1:2 with impulses lw 2 lc rgb '#1f77b4' title 'r(k)', '" + acf +
                  "' using 1:3 with lines dt 2 lc rgb '#d62728' title '95 % bound', '" + acf +
                  "' using 1:4 with lines dt 2 lc rgb '#d62728' notitle\n");
}

ForceFitFigures add_force_fit(HtmlReport& report, const ForceFitTraces& t) {
  const ForceFitFigures f = force_fit_figures(t);
  report.heading("Measured and predicted force");
  std::vector<ReportFigure> rows = {
      {"fit, 100 (1 - |y - yhat| / |y - mean(y)|)", "fit.fit_percent", f.fit_percent, "%"},
      {"RMS of measured - predicted", "fit.rms_N", f.rms_N, "N"},
      {"max |measured - predicted|", "fit.max_N", f.max_N, "N"},
  };
  if (!t.baseline.empty()) rows.push_back({"fit of the " + t.baseline_label, "fit.baseline_fit_percent", f.baseline_fit_percent, "%"});
  report.figures("Fit (as MATLAB's compare: NRMSE fit)", rows);

  const std::size_t n = t.measured.size();
  std::vector<double> x_mm(n), v_mm(n), residual(n), aside(n, NAN);
  for (std::size_t i = 0; i < n; ++i) {
    x_mm[i] = 1e3 * t.displacement[i];
    v_mm[i] = 1e3 * t.velocity[i];
    residual[i] = t.measured[i] - t.predicted[i];
    if (!t.keep.empty() && !t.keep[i]) aside[i] = t.measured[i];
  }
  const std::vector<double>& baseline = t.baseline.empty() ? aside : t.baseline;
  const std::string dat = report.data(
      "force", {"time_s", "displacement_mm", "velocity_mm_s", "measured_N", "predicted_N", "residual_N", "baseline_N", "set_aside_N"},
      {&t.time, &x_mm, &v_mm, &t.measured, &t.predicted, &residual, &baseline, &aside});
  const std::string q = "'" + dat + "'";
  // The baseline first, so that the measured and the final prediction are drawn over it.
  const auto overlay = [&](int x, const char* x_label, const char* style) {
    std::string out = format("set xlabel '%s'\nset ylabel 'force [N]'\nplot ", x_label);
    if (!t.baseline.empty())
      out += format("%s using %d:7 with %s lc rgb '#9ecae1' title '%s', ", q.c_str(), x, style, t.baseline_label.c_str());
    out += format("%s using %d:4 with %s lc rgb '#555555' title 'measured', %s using %d:5 with %s lc rgb '#d62728' title '%s'",
                  q.c_str(), x, style, q.c_str(), x, style, t.predicted_label.c_str());
    if (!t.keep.empty())
      out += format(", %s using %d:8 with points pt 6 ps 0.5 lc rgb '#ff7f0e' title 'set aside by screening'", q.c_str(), x);
    return out + "\n";
  };
  report.plot("force_time", format("%s: measured and predicted force against time, fit %.2f %%", t.name.c_str(), f.fit_percent),
              overlay(1, "time [s]", "lines lw 1"));
  report.plot("force_displacement", t.name + ": force against displacement", overlay(2, "displacement [mm]", "points pt 7 ps 0.2"));
  report.plot("force_velocity", t.name + ": force against velocity", overlay(3, "velocity [mm/s]", "points pt 7 ps 0.2"));

  report.heading("Residual");
  report.figures("Residual whiteness (as MATLAB's resid)",
                 {{"autocorrelation lags tested", "fit.acf_lags", static_cast<double>(f.lags), ""},
                  {"lag step", "fit.acf_lag_step_s", f.lag_step_s, "s"},
                  {"95 % bound, 1.96/sqrt(N)", "fit.acf_bound", f.acf_bound, ""},
                  {"share of lags outside the bound", "fit.acf_outside_fraction", f.acf_outside, "(0 to 1)"}});
  report.plot("residual_time", t.name + ": residual, measured - predicted, against time",
              "set xlabel 'time [s]'\nset ylabel 'residual [N]'\nplot " + q +
                  " using 1:6 with lines lw 1 lc rgb '#1f77b4' title 'measured - predicted'\n");
  std::vector<double> kept;
  for (std::size_t i = 0; i < n; ++i)
    if (t.keep.empty() || t.keep[i]) kept.push_back(residual[i]);
  add_autocorrelation_plot(report, kept, f.lags, 1e3 * f.lag_step_s, "lag [ms]",
                           format("%s: autocorrelation of the residual, 95 %% bounds +-%.3g (%.0f %% of lags outside)",
                                  t.name.c_str(), f.acf_bound, 100.0 * f.acf_outside));
  report.plot("residual_velocity", t.name + ": residual against velocity (structure left in the model)",
              "set xlabel 'velocity [mm/s]'\nset ylabel 'residual [N]'\nplot " + q +
                  " using 3:6 with points pt 7 ps 0.2 lc rgb '#1f77b4' title 'measured - predicted'\n");
  return f;
}

}  // namespace mrd::tools
