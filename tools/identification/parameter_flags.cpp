#include "tools/identification/parameter_flags.hpp"

#include <cmath>

#include "model/jiles_atherton_params.hpp"
#include "tools/identification/bh_objective.hpp"
#include "tools/text_format.hpp"

namespace mrd::tools {

namespace {

// Within this share of the box's width of an edge counts as on it: a bounded search that ended
// there was stopped by the box, not by the loops.
constexpr double kEdgeShare = 1e-3;

}  // namespace

std::vector<std::string> flag_parameters(const Point& best, const Bounds& box, const ParameterUncertainty& uncertainty) {
  std::vector<std::string> out;
  for (int j = 0; j < kParameterCount; ++j) {
    const std::string name(kParameterNames[static_cast<std::size_t>(j)]);
    const double lo = box.lower[j], hi = box.upper[j], v = best[j];
    const double margin = kEdgeShare * (hi - lo);
    // Every parameter's physical floor is 0: a box that reaches it does not stop the loops.
    if (hi > lo && lo > 0.0 && v <= lo + margin) out.push_back(format("%s at the search box's lower edge (%.4g)", name.c_str(), lo));
    if (hi > lo && v >= hi - margin) out.push_back(format("%s at the search box's upper edge (%.4g)", name.c_str(), hi));
    const auto index = static_cast<std::size_t>(j);
    if (index < uncertainty.standard_deviation.size() && std::isnan(uncertainty.standard_deviation[index]))
      out.push_back(name + ": not determined by the loops (no standard deviation)");
  }
  const ValidationReport validation = model::validate(to_params(best));
  for (const ValidationIssue& issue : validation.issues()) out.push_back(issue.field + ": " + issue.message);
  return out;
}

}  // namespace mrd::tools
