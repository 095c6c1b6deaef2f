#pragma once

#include <string>
#include <vector>

#include "tools/optimisation/optimiser.hpp"
#include "tools/report/fit_statistics.hpp"

namespace mrd::tools {

// Why an identified J-A set (Ms, a, alpha, k, c) should not become a config unread, one line
// each: a parameter on its search box's edge where the box is not physics' own edge (the loops
// wanted it further), one the model rejects or no real material shows (model::validate, with
// model/typical_ranges.hpp), or one the loops do not determine (no standard deviation).
// mrd-identify prints them, writes them to the JSON and the report, and --write-config refuses
// the set while there are any, unless --accept-unphysical.
[[nodiscard]] std::vector<std::string> flag_parameters(const Point& best, const Bounds& box,
                                                       const ParameterUncertainty& uncertainty);

}  // namespace mrd::tools
