#pragma once

#include <string>
#include <vector>

#include "tools/identification/bh_curve.hpp"
#include "tools/identification/identification.hpp"
#include "tools/report/fit_statistics.hpp"
#include "tools/report/html_report.hpp"

namespace mrd::tools {

// How well the final set (the polished one with --polish) fits: the NRMSE fit [%] of B over
// all points, and the parameters' standard deviations, sigma^2 (J^T J)^-1 of the B residual at
// the optimum (central differences).
struct IdentifyStatistics {
  double fit_percent = 0.0;
  ParameterUncertainty uncertainty;
  std::vector<std::string> flagged;  // flag_parameters of the final set: "unphysical" in the JSON
};
IdentifyStatistics identify_statistics(const IdentifyResult& result, const BHObjective& objective,
                                       const BHCurve& curve);

// The --json document: {"algo", "params": {Ms, a, alpha, k, c}, "rmse_T", "evaluations",
// "wall_s"}, plus the start point, the bounds and, with --polish, a separate "polish" object;
// with statistics, "fit_percent", "sigma_T" (residual standard error) and "params_sd" {Ms, a,
// alpha, k, c} of the final set, and "unphysical" (the flagged lines, [] when none).
std::string identify_json(const IdentifyResult& result, const IdentifyStatistics* statistics = nullptr);

// --report DIR: report.html with B against H measured and fitted, the residual and its
// autocorrelation, the convergence, the parameters with their standard deviations and the
// provenance. Returns "" or why not.
std::string write_identify_report(const IdentifyResult& result, const IdentifyStatistics& statistics,
                                  const BHObjective& objective, const BHCurve& curve, const Provenance& provenance,
                                  const std::string& directory);

// Human text of the same.
std::string identify_text(const IdentifyResult& result, const BHObjective& objective);

// Figure 7 (fitted over measured B-H) and Figure 8 (convergence) as PNG in `directory`.
// Returns an empty string on success, otherwise why the plot failed.
std::string plot_identification(const IdentifyResult& result, const BHObjective& objective,
                                const BHCurve& curve, const std::string& directory);

}  // namespace mrd::tools
