#pragma once

#include <string>

#include "tools/identification/bh_curve.hpp"
#include "tools/identification/identification.hpp"

namespace mrd::tools {

// The --json document: {"algo", "params": {Ms, a, alpha, k, c}, "rmse_T", "evaluations",
// "wall_s"}, plus the start point, the bounds and, with --polish, a separate "polish" object.
std::string identify_json(const IdentifyResult& result);

// Human text of the same.
std::string identify_text(const IdentifyResult& result, const BHObjective& objective);

// Figure 7 (fitted over measured B-H) and Figure 8 (convergence) as PNG in `directory`.
// Returns an empty string on success, otherwise why the plot failed.
std::string plot_identification(const IdentifyResult& result, const BHObjective& objective,
                                const BHCurve& curve, const std::string& directory);

}  // namespace mrd::tools
