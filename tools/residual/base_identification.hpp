#pragma once

#include <string>
#include <vector>

#include "model/damper_model.hpp"
#include "tools/residual/model_fit.hpp"
#include "tools/residual/search_context.hpp"

namespace mrd::tools::search {

// The base identified on `origin` (its effects kept, their linear parameters refitted among the
// linear terms): the improved PSO over every base coordinate on the runs' openings, J-A's
// sub-steps capped at 64 a sample while it explores (a trial at 30x the field gain and a
// twentieth of the pinning would otherwise take 600x the sub-steps of the origin); Nelder-Mead
// with restarts there from the swarm's best and, with `from_origin`, from the origin's
// coordinates (the config's damper, a prior, or a model already fitted), the two chains side by
// side; then Nelder-Mead on the whole fitting series from the better. `space` is the whole space.
FittedModel identify_base(Search& s, const model::DamperModel& origin, ParameterSpace& space, bool from_origin);

// Step 2: the base model from the start's damper.
FittedModel fit_base_model(Search& s, ParameterSpace& space);

// What the base fit found, one line each, for the reports: the fitted damper's figures and the
// coordinates left on their range's edge.
std::vector<std::string> describe_base(const ParameterSpace& space, const FittedModel& fit,
                                       const model::DamperModel& start);

}  // namespace mrd::tools::search
