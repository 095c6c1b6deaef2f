#pragma once

#include "tools/residual/fit_series.hpp"
#include "tools/residual/residual_result.hpp"
#include "tools/residual/term_rivalry.hpp"

namespace mrd::tools {

// The searches' J-A sub-step may grow to this fraction of |He| (JilesAthertonSettings::
// field_step_growth): far into saturation a jump then takes a few steps, at the uniform grid's
// accuracy (tests/model/test_jiles_atherton_reference.cpp; docs/PERFORMANCE.md).
inline constexpr double kSearchFieldStepGrowth = 0.02;

// Steps 1-6 of docs/CLOSING-THE-LOOP.md, "mrd-residual": fit the base model, analyse its
// residual, fit each candidate effect on the fitting blocks and validate it on the others,
// accept greedily while the best passes the threshold, then revise the set (drop an effect
// whose removal costs less than the threshold, swap one for a rejected candidate that
// validates better beside the others) and name the candidates the run cannot separate.
// Deterministic for the seed.
ResidualResult find_missing_effects(const FitSeries& series, const ResidualOptions& options);

}  // namespace mrd::tools
