#include "tools/identification/identify_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "tools/identification/parameter_flags.hpp"
#include "tools/plot/gnuplot.hpp"
#include "tools/json.hpp"
#include "tools/report/fit_statistics.hpp"
#include "tools/report/force_fit.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace {

Json params_json(const Point& x) {
  Json out = Json::object();
  for (int j = 0; j < kParameterCount; ++j) out[std::string(kParameterNames[static_cast<std::size_t>(j)])] = x[j];
  return out;
}

Point final_point(const IdentifyResult& r) { return r.polish ? r.polish->best : r.search.best; }

// Figure 8: the global best (the best of every box so far) never rises, the box's own may.
// `data`: evaluations, global best, box best.
plot::Panel convergence_panel(const std::string& data) {
  return {.x = {"evaluations", ""},
          .y = {"best fitness", "T", std::nullopt, true},
          .data = {data},
          .series = {{"best of the search box in use", plot::column(1), plot::column(3), plot::steps(plot::colour::kLightBlue)},
                     {"global best", plot::column(1), plot::column(2), plot::steps(plot::colour::kBlue, 2.0)}}};
}

std::vector<double> measured_B(const BHCurve& curve) {
  std::vector<double> B;
  for (const auto& loop : curve.loops) B.insert(B.end(), loop.B.begin(), loop.B.end());
  return B;
}

// The report's sections, in their order: the fit's figures, the parameters, the loops and their
// residual, the convergence.

void report_fit(HtmlReport& report, const IdentifyResult& r, const IdentifyStatistics& statistics,
                const BHCurve& curve, const std::string& label) {
  report.paragraph(format("J-A parameters (Eq. 1-10) identified from %zu B-H points in %zu loop(s) by %s "
                          "(Eq. 14-22 for the improved PSO).",
                          curve.points(), curve.loops.size(), label.c_str()));
  const double rmse = r.polish ? r.polish->rmse : r.fit.rmse;
  report.figures("Fit (as the JSON)", {{"fit, 100 (1 - |B - Bhat| / |B - mean(B)|)", "fit_percent", statistics.fit_percent, "%"},
                                       {"RMSE, Eq. 15", r.polish ? "polish.rmse_T" : "rmse_T", rmse, "T"},
                                       {"residual standard error", "sigma_T", statistics.uncertainty.sigma, "T"},
                                       {"model evaluations", "evaluations", static_cast<double>(r.search.evaluations), ""}});
}

void report_parameters(HtmlReport& report, const IdentifyResult& r, const IdentifyStatistics& statistics) {
  const Point best = final_point(r);
  std::vector<HtmlReport::Parameter> rows;
  static constexpr std::array<const char*, kParameterCount> kUnits = {"A/m", "A/m", "-", "A/m", "-"};
  for (std::size_t j = 0; j < static_cast<std::size_t>(kParameterCount); ++j) {
    const std::string name(kParameterNames[j]);
    rows.push_back({name, kUnits[j], best[static_cast<Eigen::Index>(j)], statistics.uncertainty.standard_deviation[j],
                    (r.polish ? "polish.params." : "params.") + name, "params_sd." + name});
  }
  report.heading("Parameters");
  report.parameters(statistics.uncertainty.singular
                        ? "Identified set (J^T J is singular: the loops do not determine every parameter)"
                        : "Identified set: standard deviations from sigma^2 (J^T J)^-1 at the optimum (central differences)",
                    rows);
  std::vector<std::string> names(kParameterNames.begin(), kParameterNames.end());
  report.correlation_matrix("Correlation of the estimates", names, statistics.uncertainty.correlation);
  std::vector<std::vector<std::string>> flagged;
  for (const std::string& line : statistics.flagged) flagged.push_back({line, "--write-config needs --accept-unphysical"});
  if (!flagged.empty()) report.table("Flagged parameters (the JSON's unphysical)", {"parameter", "why"}, flagged);
}

// The loops point by point, measured and fitted, with a NaN row after each loop so that gnuplot
// lifts the pen between loops; `point_residual` without them, for its autocorrelation.
struct LoopColumns {
  std::vector<double> index, H, measured, fitted, residual;
  std::vector<double> point_residual;
};

LoopColumns loop_columns(const BHCurve& curve, const std::vector<double>& fitted) {
  const std::vector<double> B = measured_B(curve);
  LoopColumns c;
  std::size_t i = 0;
  for (const auto& loop : curve.loops) {
    for (std::size_t j = 0; j < loop.H.size(); ++j, ++i) {
      c.H.push_back(loop.H[j]);
      c.measured.push_back(B[i]);
      c.fitted.push_back(fitted[i]);
      c.index.push_back(static_cast<double>(i));
      c.residual.push_back(B[i] - fitted[i]);
    }
    for (auto* column : {&c.H, &c.measured, &c.fitted, &c.index, &c.residual}) column->push_back(NAN);
  }
  c.point_residual.resize(B.size());
  for (std::size_t k = 0; k < B.size(); ++k) c.point_residual[k] = B[k] - fitted[k];
  return c;
}

void report_loops(HtmlReport& report, const LoopColumns& c, const std::string& label, double fit_percent) {
  report.heading("Measured and fitted B-H loops");
  const std::string dat = report.data("bh", {"point", "H_A_per_m", "B_T", "B_fitted_T", "residual_T"},
                                      {&c.index, &c.H, &c.measured, &c.fitted, &c.residual}, c.H.size());
  report.plot("bh_loops", format("B against H, measured and fitted (%s), fit %.2f %%", label.c_str(), fit_percent),
              {.x = {"H", "A/m"},
               .y = {"B", "T"},
               .data = {dat},
               .series = {{"measured", plot::column(2), plot::column(3), plot::points(plot::colour::kGrey, 0.5),
                           plot::Layer::measured},
                          {"J-A fit", plot::column(2), plot::column(4), plot::lines(plot::colour::kRed, 2.0)}}});
  report.plot("bh_time", "B point by point along the loops, measured and fitted",
              {.x = {"point", ""},
               .y = {"B", "T"},
               .data = {dat},
               .series = {{"measured", plot::column(1), plot::column(3), plot::lines(plot::colour::kDarkGrey),
                           plot::Layer::measured},
                          {"J-A fit", plot::column(1), plot::column(4), plot::lines(plot::colour::kRed)}}});
  report.heading("Residual");
  report.plot("bh_residual", "B residual, measured - fitted, point by point",
              {.x = {"point", ""},
               .y = {"residual", "T"},
               .data = {dat},
               .series = {{"measured - fitted", plot::column(1), plot::column(5), plot::lines(plot::colour::kBlue)}}});
  report.plot("bh_residual_H", "B residual against H (structure the J-A set leaves)",
              {.x = {"H", "A/m"},
               .y = {"residual", "T"},
               .data = {dat},
               .series = {{"measured - fitted", plot::column(2), plot::column(5), plot::points(plot::colour::kBlue, 0.3)}}});
  const std::size_t lags = std::min<std::size_t>(100, c.point_residual.size() / 4);
  add_autocorrelation_plot(report, c.point_residual, lags, 1.0, {"lag", "points"},
                           format("autocorrelation of the B residual, 95 %% bounds +-%.3g",
                                  autocorrelation_bound_95(c.point_residual.size())));
}

void report_convergence(HtmlReport& report, const IdentifyResult& r) {
  report.heading("Convergence");
  // The search restarts its box now and then; the global best is the best of all boxes so far
  // and never rises, the box's own best may.
  std::vector<double> evaluations, fitness, box;
  for (const auto& c : r.search.convergence) {
    evaluations.push_back(static_cast<double>(c.evaluations));
    box.push_back(c.best_fitness);
    fitness.push_back(fitness.empty() ? c.best_fitness : std::min(fitness.back(), c.best_fitness));
  }
  const std::string conv =
      report.data("convergence", {"evaluations", "best_fitness_T", "box_best_fitness_T"}, {&evaluations, &fitness, &box});
  report.plot("convergence", "best fitness of the global search against model evaluations", convergence_panel(conv));
}

}  // namespace

IdentifyStatistics identify_statistics(const IdentifyResult& r, const BHObjective& objective, const BHCurve& curve) {
  const std::vector<double> B = measured_B(curve);
  const Point best = final_point(r);
  IdentifyStatistics out;
  out.fit_percent = nrmse_fit_percent(B, objective.simulate(to_params(best)));
  const std::vector<double> x(best.data(), best.data() + best.size());
  out.uncertainty = parameter_uncertainty(
      [&](const std::vector<double>& at) {
        Point p(kParameterCount);
        for (int j = 0; j < kParameterCount; ++j) p[j] = at[static_cast<std::size_t>(j)];
        std::vector<double> e = objective.simulate(to_params(p));
        for (std::size_t i = 0; i < e.size(); ++i) e[i] = B[i] - e[i];
        return e;
      },
      x);
  out.flagged = flag_parameters(best, r.bounds, out.uncertainty);
  return out;
}

std::string identify_json(const IdentifyResult& r, const IdentifyStatistics* statistics) {
  Json out = {{"algo", std::string(algorithm_name(r.algorithm))},
              {"params", params_json(r.search.best)},
              {"rmse_T", r.fit.rmse},
              {"evaluations", r.search.evaluations},
              {"wall_s", r.wall_s},
              {"rounds", r.rounds},
              {"start", params_json(r.start)},
              {"bounds", {{"lower", params_json(r.bounds.lower)}, {"upper", params_json(r.bounds.upper)}}}};
  if (r.polish) {
    out["polish"] = {{"method", "levenberg-marquardt"},
                     {"params", params_json(r.polish->best)},
                     {"rmse_T", r.polish->rmse},
                     {"evaluations", r.polish->evaluations},
                     {"wall_s", r.polish_wall_s}};
  }
  if (statistics) {
    out["fit_percent"] = statistics->fit_percent;
    out["sigma_T"] = statistics->uncertainty.sigma;
    Json sd = Json::object();
    for (int j = 0; j < kParameterCount; ++j) {
      sd[std::string(kParameterNames[static_cast<std::size_t>(j)])] =
          statistics->uncertainty.standard_deviation[static_cast<std::size_t>(j)];
    }
    out["params_sd"] = sd;
    out["unphysical"] = statistics->flagged;
  }
  return json_text(out);
}

std::string identify_text(const IdentifyResult& r, const BHObjective& objective) {
  std::ostringstream out;
  const double rms = objective.rms_B();
  auto row = [&](const char* label, const Point& x, double rmse, std::int64_t evaluations,
                 double wall) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%-14s Ms=%-11.5g a=%-10.5g alpha=%-11.5g k=%-10.5g c=%-8.5g | RMSE %.4g T "
                  "(%.3g%% of rms B) | %lld evaluations, %.3f s\n",
                  label, x[0], x[1], x[2], x[3], x[4], rmse, 100.0 * rmse / rms,
                  static_cast<long long>(evaluations), wall);
    out << line;
  };
  out << objective.points() << " points; rms B " << format("%.9g", rms) << " T\n";
  if (r.rounds > 1) {
    out << "the best point reached a face of the estimated box; searched " << r.rounds
        << " boxes, each re-centred on the best so far\n";
  }
  out << format("start          Ms=%.9g a=%.9g alpha=%.9g k=%.9g c=%.9g\n", r.start[0], r.start[1], r.start[2],
                r.start[3], r.start[4]);
  row(std::string(algorithm_name(r.algorithm)).c_str(), r.search.best, r.fit.rmse,
      r.search.evaluations, r.wall_s);
  if (r.fit.penalised) out << "warning: the best point is penalised (non-physical)\n";
  if (r.polish) row("+ LM polish", r.polish->best, r.polish->rmse, r.polish->evaluations, r.polish_wall_s);
  return out.str();
}

std::string plot_identification(const IdentifyResult& r, const BHObjective& objective,
                                const BHCurve& curve, const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) return "cannot create " + directory + ": " + ec.message();
  const Point& best = r.polish ? r.polish->best : r.search.best;
  const auto fitted = objective.simulate(to_params(best));
  const std::string loops_file = (fs::path(directory) / "identify_bh.dat").string();
  const std::string convergence_file = (fs::path(directory) / "identify_convergence.dat").string();
  {
    std::ofstream out(loops_file);
    std::size_t i = 0;
    for (const auto& loop : curve.loops) {
      for (std::size_t j = 0; j < loop.H.size(); ++j, ++i) {
        out << loop.H[j] << ' ' << loop.B[j] << ' ' << fitted[i] << '\n';
      }
      out << "\n\n";
    }
    std::ofstream conv(convergence_file);
    double global = std::numeric_limits<double>::infinity();
    for (const auto& c : r.search.convergence) {
      global = std::min(global, c.best_fitness);
      conv << c.evaluations << ' ' << global << ' ' << c.best_fitness << '\n';
    }
  }
  const std::string label = std::string(algorithm_name(r.algorithm)) + (r.polish ? " + LM" : "");
  const plot::Figure loops{
      .output = (fs::path(directory) / "identify_bh.png").string(),
      .title = "B-H loops: measured and fitted (" + label + ", RMSE " +
               format("%.9g", r.polish ? r.polish->rmse : r.fit.rmse) + " T)",
      .panels = {{.x = {"H", "A/m"},
                  .y = {"B", "T"},
                  .data = {loops_file},
                  .series = {{"measured", plot::column(1), plot::column(2), plot::points(plot::colour::kGrey, 0.4),
                              plot::Layer::measured},
                             {"J-A fit", plot::column(1), plot::column(3), plot::lines(plot::colour::kRed, 2.0)}}}}};
  const plot::Figure convergence{.output = (fs::path(directory) / "identify_convergence.png").string(),
                                 .title = "Convergence (" + label + ")",
                                 .panels = {convergence_panel(convergence_file)}};
  return plot::draw({loops, convergence});
}

std::string write_identify_report(const IdentifyResult& r, const IdentifyStatistics& statistics,
                                  const BHObjective& objective, const BHCurve& curve, const Provenance& provenance,
                                  const std::string& directory) {
  const std::string label = std::string(algorithm_name(r.algorithm)) + (r.polish ? " + Levenberg-Marquardt" : "");
  HtmlReport report("mrd-identify: " + curve.source, directory);
  report_fit(report, r, statistics, curve, label);
  report_parameters(report, r, statistics);
  const LoopColumns loops = loop_columns(curve, objective.simulate(to_params(final_point(r))));
  report_loops(report, loops, label, statistics.fit_percent);
  report_convergence(report, r);
  report.provenance(provenance);
  return report.write();
}

}  // namespace mrd::tools
