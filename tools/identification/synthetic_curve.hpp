#pragma once

#include "model/jiles_atherton.hpp"
#include "tools/identification/bh_curve.hpp"

namespace mrd::tools {

// One major loop of the J-A model, `points` samples evenly spaced along the field path
// +H_max -> -H_max -> +H_max, simulated exactly as the identification simulates measured
// loops (LoopSimulator), so a fit of it can recover the parameters.
BHCurve synthetic_loop(const model::JilesAthertonParams& params, double H_max, std::size_t points,
                       const model::JilesAthertonSettings& settings = {});

}  // namespace mrd::tools
