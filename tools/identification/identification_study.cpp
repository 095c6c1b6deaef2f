#include "tools/identification/identification_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <Eigen/SVD>

#include "tools/identification/start_point.hpp"

namespace mrd::tools {

Spread spread_of(std::vector<double> v) {
  if (v.empty()) return {};
  std::sort(v.begin(), v.end());
  auto quantile = [&](double q) {
    const double pos = q * static_cast<double>(v.size() - 1);
    const auto i = static_cast<std::size_t>(pos);
    const double t = pos - static_cast<double>(i);
    return i + 1 < v.size() ? v[i] * (1.0 - t) + v[i + 1] * t : v[i];
  };
  return {quantile(0.5), quantile(0.25), quantile(0.75), v.front(), v.back()};
}

namespace {

struct Samples {
  std::array<std::vector<double>, kParameterCount> relative_error;
  std::vector<double> rmse, evaluations, wall;

  void add(const Point& x, const Point* truth, double rmse_T, double evals, double wall_s) {
    if (truth) {
      for (int j = 0; j < kParameterCount; ++j) {
        relative_error[static_cast<std::size_t>(j)].push_back(
            100.0 * std::fabs(x[j] - (*truth)[j]) / std::fabs((*truth)[j]));
      }
    }
    rmse.push_back(rmse_T);
    evaluations.push_back(evals);
    wall.push_back(wall_s);
  }

  [[nodiscard]] StudyRow row(std::string label) const {
    StudyRow r;
    r.label = std::move(label);
    for (std::size_t j = 0; j < relative_error.size(); ++j) {
      r.relative_error_percent[j] = spread_of(relative_error[j]);
    }
    r.rmse = spread_of(rmse);
    r.evaluations = spread_of(evaluations);
    r.wall_s = spread_of(wall);
    return r;
  }
};

std::vector<StudyRow> run_study(const BHCurve& curve, const StudyOptions& options,
                                const std::optional<Point>& truth) {
  const BHObjective objective(curve, options.settings);
  std::vector<StudyRow> rows;
  const std::int64_t runs = static_cast<std::int64_t>(options.algorithms.size()) * options.seeds;
  std::int64_t done = 0;
  double best_rmse = std::numeric_limits<double>::quiet_NaN();
  for (const Algorithm algorithm : options.algorithms) {
    Samples search, polished;
    const bool polish = options.polished_row && algorithm == Algorithm::kImprovedPso;
    for (int seed = 1; seed <= options.seeds; ++seed) {
      IdentifyOptions o;
      o.algorithm = algorithm;
      o.budget = options.budget;
      o.seed = static_cast<std::uint64_t>(seed);
      o.threads = options.threads;
      o.improved = options.improved;
      if (truth) {
        o.start = *truth;  // Section 4.1: +-100% around the true values
      }
      o.polish = polish;
      o.polish_evaluations = options.polish_evaluations;
      const IdentifyResult r = identify(objective, curve, o);
      if (options.first_seed_runs && seed == 1) options.first_seed_runs->push_back(r);
      const Point* t = truth ? &*truth : nullptr;
      search.add(r.search.best, t, r.fit.rmse, static_cast<double>(r.search.evaluations), r.wall_s);
      if (r.polish) {
        polished.add(r.polish->best, t, r.polish->rmse,
                     static_cast<double>(r.search.evaluations + r.polish->evaluations),
                     r.wall_s + r.polish_wall_s);
      }
      const double rmse = r.polish ? std::fmin(r.fit.rmse, r.polish->rmse) : r.fit.rmse;
      // A diverged run (NaN) never becomes the best, nor lets a worse one in after it.
      if (std::isfinite(rmse) && (std::isnan(best_rmse) || rmse < best_rmse)) best_rmse = rmse;
      if (options.progress) {
        options.progress->report({.stage = options.stage, .round = seed, .candidate = algorithm_name(algorithm),
                                  .done = ++done, .total = runs, .best_error = best_rmse, .unit = "T RMSE"});
      }
    }
    rows.push_back(search.row(std::string(algorithm_name(algorithm))));
    if (polish) rows.push_back(polished.row(std::string(algorithm_name(algorithm)) + " + LM"));
  }
  return rows;
}

std::string cell(const Spread& s, const char* format) {
  auto text = [format](double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, format, x);
    return std::string(buffer);
  };
  return text(s.median) + " [" + text(s.q25) + ", " + text(s.q75) + "]";
}

}  // namespace

std::vector<StudyRow> parameter_recovery_study(const model::JilesAthertonParams& truth,
                                               const BHCurve& curve, const StudyOptions& options) {
  return run_study(curve, options, to_point(truth));
}

std::vector<StudyRow> measured_fit_study(const BHCurve& curve, const StudyOptions& options) {
  return run_study(curve, options, std::nullopt);
}

Sensitivity parameter_sensitivity(const BHObjective& objective, const Point& x) {
  const auto n = static_cast<Eigen::Index>(objective.points());
  Eigen::MatrixXd J(n, kParameterCount);
  const double step = 1e-6;
  const double scale = 1.0 / std::sqrt(static_cast<double>(n));
  for (int j = 0; j < kParameterCount; ++j) {
    Point up = x, down = x;
    up[j] *= 1.0 + step;
    down[j] *= 1.0 - step;
    const auto B_up = objective.simulate(to_params(up));
    const auto B_down = objective.simulate(to_params(down));
    for (Eigen::Index i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      J(i, j) = scale * (B_up[k] - B_down[k]) / (2.0 * step);
    }
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinV);
  return {svd.singularValues(), svd.matrixV()};
}

std::string sensitivity_markdown(const Sensitivity& s) {
  std::string out = "| singular value [T] |";
  for (const auto name : kParameterNames) out.append(" ").append(name).append(" |");
  out += "\n|---|---|---|---|---|---|\n";
  char buffer[32];
  for (Eigen::Index i = 0; i < s.singular_values.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, "%.3g", s.singular_values[i]);
    out.append("| ").append(buffer).append(" |");
    for (Eigen::Index j = 0; j < s.directions.rows(); ++j) {
      std::snprintf(buffer, sizeof buffer, "%+.3f", s.directions(j, i));
      out.append(" ").append(buffer).append(" |");
    }
    out += "\n";
  }
  return out;
}

std::string recovery_table_markdown(const std::vector<StudyRow>& rows) {
  std::string out =
      "| algorithm | Ms | a | alpha | k | c | RMSE [T] | evaluations | wall [s] |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    out += "| " + r.label;
    for (const auto& e : r.relative_error_percent) out += " | " + cell(e, "%.3g");
    out += " | " + cell(r.rmse, "%.2e") + " | " + cell(r.evaluations, "%.0f") + " | " +
           cell(r.wall_s, "%.2f") + " |\n";
  }
  return out;
}

std::string fit_table_markdown(const std::vector<StudyRow>& rows, double rms_B) {
  std::string out =
      "| algorithm | RMSE [T] | relative RMSE [%] | best RMSE [T] | evaluations | wall [s] |\n"
      "|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    const double to_percent = 100.0 / rms_B;
    const Spread relative{r.rmse.median * to_percent, r.rmse.q25 * to_percent,
                          r.rmse.q75 * to_percent, r.rmse.min * to_percent,
                          r.rmse.max * to_percent};
    char best[32];
    std::snprintf(best, sizeof best, "%.4g", r.rmse.min);
    out += "| " + r.label + " | " + cell(r.rmse, "%.4g") + " | " + cell(relative, "%.3g") +
           " | " + best + " | " + cell(r.evaluations, "%.0f") + " | " + cell(r.wall_s, "%.2f") + " |\n";
  }
  return out;
}

}  // namespace mrd::tools
