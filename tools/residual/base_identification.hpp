#pragma once

#include <array>
#include <string>
#include <vector>

#include "model/damper_model.hpp"
#include "tools/residual/model_fit.hpp"
#include "tools/residual/search_context.hpp"

namespace mrd::tools::search {

// The base identified on `origin` (its effects kept, their linear parameters refitted among the
// linear terms): `swarms` runs of the improved PSO over every base coordinate on the runs'
// openings, each of its own seed, J-A's sub-steps capped at 64 a sample while they explore (a
// trial at 30x the field gain and a twentieth of the pinning would otherwise take 600x the
// sub-steps of the origin); Nelder-Mead with restarts there from each swarm's best and, with
// `from_origin`, from the origin's coordinates (the config's damper, a prior, or a model already
// fitted), the chains side by side (and one more from `also_from`, when given, and one in the
// other form of Eq. 10 with `both_forms`, the better form kept); then
// Nelder-Mead on the whole fitting series from the best. `space` is the whole space.
// A first identification takes two swarms: with the material, the yield law and the shapes
// free, one swarm's best lands in a poor basin now and then (on the random-damper study's clean
// runs, 5 of 30 above 1.3x the noise with two, 6 with one, one of them at 3.4x). A
// re-identification after an accepted effect starts a chain from the model already fitted, and
// one swarm serves.
// How much better (a share of the fitting RMS on the runs' openings) the other form of Eq. 10
// must fit before it replaces the origin's (docs/CLOSING-THE-LOOP.md, step 2).
inline constexpr double kFormMargin = 0.01;

// The form of Eq. 10 a first identification keeps, from each form's best fitting RMS on the
// openings (Search::form_fitting_rms): the origin's unless the other fits better by kFormMargin.
// Where an unnamed effect dominates the residual the two differ by hundredths of a per cent, and
// a switch on that would be chance (the random dampers' single-effect runs: 0.01-0.03 %).
model::JilesAthertonForm kept_form(model::JilesAthertonForm origin, const std::array<double, 2>& form_fitting_rms);

struct BaseStarts {
  int swarms = 1;                    // at least 1
  bool from_origin = true;           // a chain from the origin's coordinates
  const Point* also_from = nullptr;  // and one from here, when given
  // A chain in the other form of Eq. 10 from the first swarm's best, where the current varies,
  // kept when it fits better by kFormMargin: a first identification decides the form, a
  // re-identification keeps the origin's.
  bool both_forms = false;
};
FittedModel identify_base(Search& s, const model::DamperModel& origin, ParameterSpace& space, const BaseStarts& starts);

// Step 2: the base model from the start's damper.
FittedModel fit_base_model(Search& s, ParameterSpace& space);

// Step 3b, the robust loss (--robust-fit). Where the least-squares base leaves a material share
// of the fitting series' weight to Huber's loss (a fault no screening rule named), the base is
// identified again under Cauchy's loss, its knee at the tuning times the least-squares
// residual's robust sigma (a fault bends the swarm's exploration, not only the last
// refinement), then refined with the knee from its own residual, narrower: a fault's pull
// fades with the knee. Every later fit and judgement runs under Huber's loss at that knee: a
// candidate that explains samples far off the base (stroke-end air) still gains their whole
// distance, linearly, where Cauchy's would hardly see it coming. `refits` becomes 1 when it
// identified the base again.
FittedModel refit_robustly(Search& s, ParameterSpace& space, FittedModel base, int& refits);

// What the base fit found, one line each, for the reports: the fitted damper's figures and the
// coordinates left on their range's edge.
// `form_fitting_rms`: the identification's best in each form of Eq. 10 (Search::form_fitting_rms).
std::vector<std::string> describe_base(const ParameterSpace& space, const FittedModel& fit,
                                       const model::DamperModel& start, const SeriesScales& scales,
                                       const std::array<double, 2>& form_fitting_rms);

}  // namespace mrd::tools::search
