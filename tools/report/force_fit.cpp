#include "tools/report/force_fit.hpp"

#include <cmath>
#include <limits>

#include "tools/report/fit_statistics.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace {

// The samples [from, to) of one run.
struct RunSpan {
  std::size_t from = 0;
  std::size_t to = 0;
};

std::vector<RunSpan> run_spans(const ForceFitTraces& t) {
  std::vector<RunSpan> out;
  if (t.run_starts.size() < 2) return {{0, t.measured.size()}};
  for (std::size_t r = 0; r < t.run_starts.size(); ++r)
    out.push_back({t.run_starts[r], r + 1 < t.run_starts.size() ? t.run_starts[r + 1] : t.measured.size()});
  return out;
}

// measured - `model` (the final prediction unless another is named) over the kept samples.
std::vector<double> kept_residual(const ForceFitTraces& t, RunSpan span, const std::vector<double>& model) {
  std::vector<double> e;
  e.reserve(span.to - span.from);
  for (std::size_t i = span.from; i < span.to; ++i)
    if (t.keep.empty() || t.keep[i]) e.push_back(t.measured[i] - model[i]);
  return e;
}

std::vector<double> kept_residual(const ForceFitTraces& t, RunSpan span) { return kept_residual(t, span, t.predicted); }

std::vector<double> kept_residual(const ForceFitTraces& t) { return kept_residual(t, {0, t.measured.size()}); }

// RMS over the range of the measured force on the span's kept samples (mrd-replay's nrmse); NaN for a flat force.
double nrmse_of(const ForceFitTraces& t, RunSpan span, double rms) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = span.from; i < span.to; ++i) {
    if (!t.keep.empty() && !t.keep[i]) continue;
    lo = std::min(lo, t.measured[i]);
    hi = std::max(hi, t.measured[i]);
  }
  return hi > lo ? rms / (hi - lo) : std::numeric_limits<double>::quiet_NaN();
}

double rms_of(const std::vector<double>& e, double& max_abs) {
  double sum = 0.0;
  for (const double x : e) {
    sum += x * x;
    max_abs = std::max(max_abs, std::abs(x));
  }
  return e.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(e.size()));
}

double share_outside(const std::vector<double>& r, double bound) {
  std::size_t outside = 0;
  for (std::size_t k = 1; k < r.size(); ++k) outside += std::abs(r[k]) > bound ? 1 : 0;
  return r.size() > 1 ? static_cast<double>(outside) / static_cast<double>(r.size() - 1) : 0.0;
}

double step_of(const ForceFitTraces& t, RunSpan span) {
  return span.to > span.from + 1 ? (t.time[span.to - 1] - t.time[span.from]) / static_cast<double>(span.to - span.from - 1)
                                 : 0.0;
}

// The runs' autocorrelations averaged by their kept samples: each at its own step, so a
// residual's correlation is never measured across a boundary or at another run's rate.
std::vector<double> pooled_autocorrelation(const ForceFitTraces& t, std::size_t lags, std::size_t& samples) {
  std::vector<double> pooled;
  samples = 0;
  // A run too short for every lag (one mostly screened out) would cut the others' lags: it is
  // left out whenever a run long enough exists.
  const std::vector<RunSpan> spans = run_spans(t);
  bool any_long = false;
  for (const RunSpan span : spans) any_long = any_long || kept_residual(t, span).size() > 4 * lags;
  for (const RunSpan span : spans) {
    const std::vector<double> e = kept_residual(t, span);
    if (any_long && e.size() <= 4 * lags) continue;
    const std::vector<double> r = autocorrelation(e, lags);
    if (r.empty()) continue;
    if (pooled.empty() || r.size() < pooled.size()) pooled.resize(r.size());
    for (std::size_t k = 0; k < pooled.size(); ++k) pooled[k] += static_cast<double>(e.size()) * r[k];
    samples += e.size();
  }
  for (double& r : pooled) r /= static_cast<double>(std::max<std::size_t>(samples, 1));
  return pooled;
}

// The runs' cross-correlations of an input with the residual on the kept samples, averaged by
// their kept samples as the autocorrelation is; lags -lags..lags at index k + lags. `bound`: the
// 95 % bound of an estimate when the two are unrelated. A residual is seldom white and an input
// (a sine, a band-limited motion) never is, so 1.96/sqrt(N) would call almost every lag of
// two unrelated smooth signals significant: Bartlett's variance (1 + 2 sum_m ru(m) re(m)) / N,
// as MATLAB's resid widens its band (bartlett_factor).
std::vector<double> pooled_cross_correlation(const ForceFitTraces& t, const std::vector<double>& input, std::size_t lags,
                                             double& bound) {
  std::vector<double> pooled(2 * lags + 1, 0.0);
  std::size_t samples = 0;
  double variance = 0.0;  // sum over runs of N_r S_r; the pooled variance is that over N^2
  for (const RunSpan span : run_spans(t)) {
    std::vector<double> u, e;
    for (std::size_t i = span.from; i < span.to; ++i)
      if (t.keep.empty() || t.keep[i]) {
        u.push_back(input[i]);
        e.push_back(t.measured[i] - t.predicted[i]);
      }
    if (e.size() <= 4 * lags) continue;
    const std::vector<double> r = cross_correlation(u, e, lags);
    if (r.size() != pooled.size()) continue;
    for (std::size_t k = 0; k < r.size(); ++k) pooled[k] += static_cast<double>(e.size()) * r[k];
    const double spread = bartlett_factor(u, e);
    variance += static_cast<double>(e.size()) * (std::isfinite(spread) ? std::max(spread, 1e-3) : 1.0);
    samples += e.size();
  }
  if (samples == 0) return {};
  for (double& r : pooled) r /= static_cast<double>(samples);
  bound = 1.96 * std::sqrt(variance) / static_cast<double>(samples);
  return pooled;
}

InputCorrelation input_correlation(const std::string& name, const std::vector<double>& r, double bound, double lag_step) {
  InputCorrelation c{name, 0.0, 0.0, bound, 0.0, r};
  if (r.empty()) return {name, NAN, NAN, NAN, NAN, {}};
  const std::size_t lags = r.size() / 2;
  std::size_t outside = 0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    outside += std::abs(r[k]) > bound ? 1 : 0;
    if (std::abs(r[k]) > c.max_abs_r) {
      c.max_abs_r = std::abs(r[k]);
      c.at_lag_s = (static_cast<double>(k) - static_cast<double>(lags)) * lag_step;
    }
  }
  c.outside = static_cast<double>(outside) / static_cast<double>(r.size());
  return c;
}

// After the lag step is known (0 when the runs' rates differ: lags then in samples).
void add_input_correlations(const ForceFitTraces& t, ForceFitFigures& f) {
  const double step = f.lag_step_s > 0.0 ? f.lag_step_s : 1.0;
  for (const auto& [name, input] : {std::pair{"velocity", &t.velocity}, std::pair{"displacement", &t.displacement}}) {
    if (input->size() != t.measured.size()) continue;
    double bound = NAN;
    const std::vector<double> r = pooled_cross_correlation(t, *input, f.lags, bound);
    f.inputs.push_back(input_correlation(name, r, bound, step));
  }
}

}  // namespace

ForceFitFigures force_fit_figures(const ForceFitTraces& t, std::size_t lags) {
  ForceFitFigures f;
  f.fit_percent = nrmse_fit_percent(t.measured, t.predicted, t.keep);
  f.baseline_fit_percent = t.baseline.empty() ? std::numeric_limits<double>::quiet_NaN()
                                              : nrmse_fit_percent(t.measured, t.baseline, t.keep);
  f.rms_N = rms_of(kept_residual(t), f.max_N);
  f.nrmse = nrmse_of(t, {0, t.measured.size()}, f.rms_N);
  f.reference_fit_percent = f.reference_rms_N = std::numeric_limits<double>::quiet_NaN();
  if (t.reference.size() == t.measured.size()) {
    f.reference_fit_percent = nrmse_fit_percent(t.measured, t.reference, t.keep);
    double max = 0.0;
    f.reference_rms_N = rms_of(kept_residual(t, {0, t.measured.size()}, t.reference), max);
  }
  std::size_t samples = 0;
  const std::vector<double> r = pooled_autocorrelation(t, lags, samples);
  f.lags = r.empty() ? 0 : r.size() - 1;
  f.acf_bound = autocorrelation_bound_95(samples);
  f.acf_outside = share_outside(r, f.acf_bound);
  const std::vector<RunSpan> spans = run_spans(t);
  f.lag_step_s = step_of(t, spans.front());
  if (t.run_starts.size() < 2) {
    add_input_correlations(t, f);
    return f;
  }
  for (std::size_t k = 0; k < spans.size(); ++k) {
    const RunSpan span = spans[k];
    RunFitFigures run;
    run.name = k < t.run_names.size() ? t.run_names[k] : "run " + std::to_string(k + 1);
    const auto slice = [&](const std::vector<double>& v) { return std::vector<double>(v.begin() + span.from, v.begin() + span.to); };
    std::vector<bool> keep = t.keep.empty() ? std::vector<bool>() : std::vector<bool>(t.keep.begin() + span.from, t.keep.begin() + span.to);
    run.fit_percent = nrmse_fit_percent(slice(t.measured), slice(t.predicted), keep);
    const std::vector<double> e = kept_residual(t, span);
    run.samples = e.size();
    run.rms_N = rms_of(e, run.max_N);
    run.nrmse = nrmse_of(t, span, run.rms_N);
    run.lag_step_s = step_of(t, span);
    run.acf_outside = share_outside(autocorrelation(e, lags), autocorrelation_bound_95(e.size()));
    // One lag step for all only when the runs share a rate (within 1 %).
    if (std::abs(run.lag_step_s - f.lag_step_s) > 0.01 * f.lag_step_s) f.lag_step_s = 0.0;
    f.runs.push_back(std::move(run));
  }
  add_input_correlations(t, f);
  return f;
}

Json force_fit_json(const ForceFitFigures& f) {
  Json out = {{"fit_percent", f.fit_percent},   {"nrmse", f.nrmse},   {"rms_N", f.rms_N},
              {"max_N", f.max_N},               {"baseline_fit_percent", f.baseline_fit_percent},
              {"acf_lags", f.lags},             {"acf_lag_step_s", f.lag_step_s},
              {"acf_bound", f.acf_bound},       {"acf_outside_fraction", f.acf_outside}};
  if (std::isfinite(f.reference_rms_N)) {
    out["reference_fit_percent"] = f.reference_fit_percent;
    out["reference_rms_N"] = f.reference_rms_N;
  }
  Json inputs = Json::array();
  for (const InputCorrelation& c : f.inputs)
    inputs.push_back({{"input", c.input}, {"max_abs_r", c.max_abs_r}, {"at_lag_s", c.at_lag_s}, {"bound", c.bound},
                      {"outside_fraction", c.outside}});
  out["input_xcorr"] = inputs;
  if (f.runs.empty()) return out;
  Json runs = Json::array();
  for (const RunFitFigures& r : f.runs)
    runs.push_back({{"run", r.name}, {"samples", r.samples}, {"fit_percent", r.fit_percent}, {"nrmse", r.nrmse}, {"rms_N", r.rms_N},
                    {"max_N", r.max_N}, {"acf_lag_step_s", r.lag_step_s}, {"acf_outside_fraction", r.acf_outside}});
  out["runs"] = runs;
  return out;
}

std::string per_run_text(const ForceFitFigures& f) {
  std::string out;
  if (f.runs.empty()) return out;
  out += "per run (final model, kept samples):\n";
  for (const RunFitFigures& r : f.runs)
    out += format("  %-40s fit %6.2f %%  NRMSE %6.4f  RMS %9.4g N  max %9.4g N  %7zu samples at %.4g ms\n", r.name.c_str(),
                  r.fit_percent, r.nrmse, r.rms_N, r.max_N, r.samples, 1e3 * r.lag_step_s);
  return out;
}

namespace {

// A correlation's whole range, asked for: its scale read at a glance, and |r| <= 1 cannot be cut.
constexpr plot::Range kCorrelationRange{-1.0, 1.0};

void plot_autocorrelation(HtmlReport& report, const std::vector<double>& r, double bound, double lag_step,
                          const plot::Axis& lag_axis, const std::string& caption) {
  std::vector<double> lag(r.size()), upper(r.size(), bound), lower(r.size(), -bound);
  for (std::size_t k = 0; k < r.size(); ++k) lag[k] = static_cast<double>(k) * lag_step;
  const std::string acf = report.data("autocorrelation", {"lag", "r", "upper_95", "lower_95"}, {&lag, &r, &upper, &lower});
  report.plot("residual_autocorrelation", caption,
              {.x = lag_axis, .y = {"autocorrelation", "-", kCorrelationRange}, .data = {acf},
               .series = {{"r(k)", plot::column(1), plot::column(2), plot::impulses(plot::colour::kBlue)},
                          {"95 % bound", plot::column(1), plot::column(3), plot::dashed(plot::colour::kRed)},
                          {"", plot::column(1), plot::column(4), plot::dashed(plot::colour::kRed)}}});
}

}  // namespace

namespace {

// The residual's cross-correlation with each input against the lag, between the 95 % bounds.
void add_input_correlation_plot(HtmlReport& report, const std::string& name, const ForceFitFigures& f) {
  if (f.inputs.empty() || f.inputs.front().r.empty()) return;
  const bool in_ms = f.lag_step_s > 0.0;
  const std::size_t lags = f.inputs.front().r.size() / 2;
  std::vector<double> lag;
  for (std::size_t k = 0; k <= 2 * lags; ++k)
    lag.push_back((static_cast<double>(k) - static_cast<double>(lags)) * (in_ms ? 1e3 * f.lag_step_s : 1.0));
  std::vector<std::string> names = {"lag"};
  std::vector<const std::vector<double>*> columns = {&lag};
  std::vector<std::vector<double>> bounds;  // each input's own, +-
  bounds.reserve(4);
  std::vector<ReportFigure> rows;
  std::vector<plot::Series> series;
  const char* colours[] = {plot::colour::kBlue, plot::colour::kGreen};
  for (std::size_t i = 0; i < f.inputs.size() && i < 2; ++i) {
    const InputCorrelation& c = f.inputs[i];
    if (c.r.size() != lag.size()) continue;
    names.push_back(c.input);
    columns.push_back(&c.r);
    series.push_back({c.input, plot::column(1), plot::column(static_cast<int>(columns.size())), plot::lines(colours[i], 2.0)});
    bounds.emplace_back(lag.size(), c.bound);
    bounds.emplace_back(lag.size(), -c.bound);
    names.push_back(c.input + "_upper_95");
    columns.push_back(&bounds[bounds.size() - 2]);
    names.push_back(c.input + "_lower_95");
    columns.push_back(&bounds.back());
    const int upper = static_cast<int>(columns.size()) - 1;
    series.push_back({c.input + " 95 % bound", plot::column(1), plot::column(upper), plot::dashed(colours[i])});
    series.push_back({"", plot::column(1), plot::column(upper + 1), plot::dashed(colours[i])});
    const std::string key = "fit.input_xcorr." + std::to_string(i);
    rows.push_back({c.input + ": largest |r|", key + ".max_abs_r", c.max_abs_r, ""});
    rows.push_back({c.input + ": at lag", key + ".at_lag_s", c.at_lag_s, in_ms ? "s" : "samples"});
    rows.push_back({c.input + ": 95 % bound (Bartlett, the two autocorrelations)", key + ".bound", c.bound, ""});
    rows.push_back({c.input + ": share of lags outside the bound", key + ".outside_fraction", c.outside, "(0 to 1)"});
  }
  report.figures("Residual against the inputs (as MATLAB's resid: cross-correlation, lag > 0 when the residual follows)", rows);
  const std::string xcorr = report.data("xcorr", names, columns);
  report.plot("residual_input_correlation",
              format("%s: cross-correlation of the residual with the velocity and the displacement, each between its "
                     "95 %% bounds (dashed)",
                     name.c_str()),
              {.x = {"lag", in_ms ? "ms" : "samples"},
               .y = {"cross-correlation", "-", kCorrelationRange},
               .data = {xcorr},
               .series = std::move(series)});
}

}  // namespace

std::vector<TimeMarker> run_markers(const std::vector<double>& time, const std::vector<std::size_t>& run_starts,
                                    const std::vector<std::string>& run_names) {
  std::vector<TimeMarker> out;
  if (run_starts.size() < 2) return out;
  for (std::size_t r = 0; r < run_starts.size(); ++r) {
    if (run_starts[r] >= time.size()) break;  // a run with no sample left has nothing to mark
    out.push_back({time[run_starts[r]], run_starts.size() <= 8 && r < run_names.size() ? run_names[r] : std::string()});
  }
  return out;
}

std::vector<plot::Marker> run_boundaries(const std::vector<double>& time, const std::vector<std::size_t>& run_starts,
                                         const std::vector<std::string>& run_names) {
  std::vector<plot::Marker> out;
  for (const TimeMarker& m : run_markers(time, run_starts, run_names))
    out.push_back({m.at, m.label, !out.empty()});  // the first run begins at the axis
  return out;
}

void add_autocorrelation_plot(HtmlReport& report, const std::vector<double>& residual, std::size_t lags,
                              double lag_step, const plot::Axis& lag_axis, const std::string& caption) {
  plot_autocorrelation(report, autocorrelation(residual, lags), autocorrelation_bound_95(residual.size()), lag_step,
                       lag_axis, caption);
}

namespace {

// The fit's table (final model, base model, reference) and, with several runs, the per-run one.
void add_fit_tables(HtmlReport& report, const ForceFitTraces& t, const ForceFitFigures& f) {
  std::vector<ReportFigure> rows = {
      {"fit, 100 (1 - |y - yhat| / |y - mean(y)|)", "fit.fit_percent", f.fit_percent, "%"},
      {"NRMSE, RMS / the measured force's range", "fit.nrmse", f.nrmse, "-"},
      {"RMS of measured - predicted", "fit.rms_N", f.rms_N, "N"},
      {"max |measured - predicted|", "fit.max_N", f.max_N, "N"},
  };
  if (!t.baseline.empty()) rows.push_back({"fit of the " + t.baseline_label, "fit.baseline_fit_percent", f.baseline_fit_percent, "%"});
  if (t.reference.size() == t.measured.size()) {
    rows.push_back({"fit of " + t.reference_label, "fit.reference_fit_percent", f.reference_fit_percent, "%"});
    rows.push_back({"RMS of measured - " + t.reference_label, "fit.reference_rms_N", f.reference_rms_N, "N"});
  }
  report.figures("Fit (as MATLAB's compare: NRMSE fit)", rows);
  if (!f.runs.empty()) {
    std::vector<std::vector<std::string>> per_run;
    for (const RunFitFigures& r : f.runs)
      per_run.push_back({r.name, std::to_string(r.samples), format("%.2f", r.fit_percent), format("%.4f", r.nrmse), format("%.4g", r.rms_N),
                         format("%.4g", r.max_N), format("%.4g", 1e3 * r.lag_step_s), format("%.0f", 100.0 * r.acf_outside)});
    report.table("Per run (the JSON's fit.runs)",
                 {"run", "kept samples", "fit [%]", "NRMSE", "RMS [N]", "max [N]", "sample step [ms]", "lags outside the 95 % bound [%]"},
                 per_run);
  }
}

}  // namespace

ForceFitFigures add_force_fit(HtmlReport& report, const ForceFitTraces& t) {
  const ForceFitFigures f = force_fit_figures(t);
  report.heading("Measured and predicted force");
  add_fit_tables(report, t, f);

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
  // The baseline under the final model, the measured over both, the samples set aside over it.
  const auto overlay = [&](int x, plot::Axis x_axis) {
    plot::Panel panel{.x = std::move(x_axis), .y = {"force", "N"}, .data = {dat}};
    if (!t.baseline.empty())
      panel.series.push_back({t.baseline_label, plot::column(x), plot::column(7), plot::points(plot::colour::kLightBlue)});
    panel.series.push_back({t.predicted_label, plot::column(x), plot::column(5), plot::points(plot::colour::kRed)});
    panel.series.push_back({"measured", plot::column(x), plot::column(4), plot::points(plot::colour::kDarkGrey),
                            plot::Layer::measured});
    if (!t.keep.empty())
      panel.series.push_back({"set aside by screening", plot::column(x), plot::column(8), plot::rings(plot::colour::kOrange),
                              plot::Layer::note});
    return panel;
  };
  const bool several = t.run_starts.size() > 1;
  const char* time_label = several ? "time, each run after the one before [s]" : "time [s]";
  const std::vector<TimeMarker> markers = run_markers(t.time, t.run_starts, t.run_names);
  TimeChart force_chart{"force_time", format("%s: measured and predicted force against time, fit %.2f %%", t.name.c_str(), f.fit_percent),
                        time_label, "force [N]", &t.time, {}, markers};
  if (!t.baseline.empty()) force_chart.series.push_back({t.baseline_label, &t.baseline, plot::colour::kLightBlue});
  if (t.reference.size() == n) force_chart.series.push_back({t.reference_label, &t.reference, plot::colour::kGreen});
  force_chart.series.push_back({t.predicted_label, &t.predicted, plot::colour::kRed});
  force_chart.series.push_back({"measured", &t.measured, plot::colour::kDarkGrey});  // on top: the data, not the model
  if (!t.keep.empty()) force_chart.series.push_back({"set aside by screening", &aside, plot::colour::kOrange, 2.0, true});
  report.time_chart(force_chart);
  report.plot("force_displacement", t.name + ": force against displacement", overlay(2, {"displacement", "mm"}),
              HtmlReport::Drawing::raster);
  report.plot("force_velocity", t.name + ": force against velocity", overlay(3, {"velocity", "mm/s"}),
              HtmlReport::Drawing::raster);

  report.heading("Residual");
  report.figures("Residual whiteness (as MATLAB's resid)",
                 {{"autocorrelation lags tested", "fit.acf_lags", static_cast<double>(f.lags), ""},
                  {"lag step", "fit.acf_lag_step_s", f.lag_step_s, "s"},
                  {"95 % bound, 1.96/sqrt(N)", "fit.acf_bound", f.acf_bound, ""},
                  {"share of lags outside the bound", "fit.acf_outside_fraction", f.acf_outside, "(0 to 1)"}});
  report.time_chart({"residual_time", t.name + ": residual, measured - predicted, against time", time_label, "residual [N]",
                     &t.time, {{"measured - predicted", &residual, plot::colour::kBlue}}, markers});
  std::size_t pooled_samples = 0;
  const std::vector<double> r = pooled_autocorrelation(t, f.lags, pooled_samples);
  const bool in_ms = f.lag_step_s > 0.0;
  plot_autocorrelation(report, r, f.acf_bound, in_ms ? 1e3 * f.lag_step_s : 1.0,
                       {"lag", in_ms ? "ms" : "samples, each run at its own rate"},
                           format("%s: autocorrelation of the residual, 95 %% bounds +-%.3g (%.0f %% of lags outside)",
                                  t.name.c_str(), f.acf_bound, 100.0 * f.acf_outside));
  add_input_correlation_plot(report, t.name, f);
  report.plot("residual_velocity", t.name + ": residual against velocity (structure left in the model)",
              {.x = {"velocity", "mm/s"},
               .y = {"residual", "N"},
               .data = {dat},
               .series = {{"measured - predicted", plot::column(3), plot::column(6), plot::points(plot::colour::kBlue)}}},
              HtmlReport::Drawing::raster);
  return f;
}

}  // namespace mrd::tools
