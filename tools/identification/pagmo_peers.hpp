#pragma once

#include <cstdint>
#include <string_view>

#include "tools/identification/bh_objective.hpp"

namespace mrd::tools {

enum class PagmoAlgorithm { kPso, kDe, kSade, kCmaes };

// pagmo2's algorithm on the same objective and budget, as a reference peer. pagmo's
// population algorithms evaluate serially, so these runs use one thread.
OptimisationResult run_pagmo(PagmoAlgorithm algorithm, const BHObjective& objective,
                             const Bounds& bounds, const Budget& budget, std::uint64_t seed);

}  // namespace mrd::tools
