#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/damper_model.hpp"
#include "model/effects/effect_set.hpp"
#include "tools/residual/fit_series.hpp"
#include "tools/residual/model_fit.hpp"

namespace mrd::tools {

// What the searches need to know of the series to set their ranges: the scales the effects'
// descriptors read (model::RunScales), and what the current does.
struct SeriesScales : model::RunScales {
  bool current_varies = false;  // over the series, more than 5 % of its largest |value|
  bool current_steps = false;   // within a run: fast changes, so a coil lag shows
};
SeriesScales series_scales(const FitSeries& series);

// The base model's free parameters, set on `origin` (the config's damper, or the default):
//   log10 of the field gain N / Le [turns/m] (Eq. 9: how fast the current walks up the
//     material's B-H curve), within 1.5 decades of the origin's, only when the current varies;
//   log10 of the sign regularisation velocity v_s [m/s] of Eq. 11.
// With the linear terms (force scale, viscous coefficient) this is the lumped equivalent the
// docs describe: the J-A material's shape is kept, its scale in current and force is fitted.
// With FieldGain::kKept the gain stays the origin's, so every point shares the origin's B.
enum class FieldGain { kFitted, kKept };
ParameterSpace base_space(const model::DamperModel& origin, const model::DamperModel& start,
                          const SeriesScales& scales, FieldGain gain = FieldGain::kFitted);
// The base coordinates of `model` in that space.
Point base_coordinates(const model::DamperModel& model, const SeriesScales& scales,
                       FieldGain gain = FieldGain::kFitted);

// The field gain alone, the rest of `origin` kept (its effects' linear parameters refitted
// among the linear terms): the magnetic step of a refinement that otherwise shares B.
ParameterSpace field_gain_space(const model::DamperModel& origin, const model::DamperModel& start);

// The candidate effect (its descriptor, model/effects/) added to `model`, over the parameters
// identifiable from a run (docs/CLOSING-THE-LOOP.md lists them and their ranges).
ParameterSpace effect_space(const model::EffectInfo& effect, const model::DamperModel& model,
                            const SeriesScales& scales);

// The coordinates of the effect in `model`, in effect_space(effect, ...): where a joint
// refinement of effects already accepted starts.
Point effect_coordinates(const model::EffectInfo& effect, const model::DamperModel& model, const SeriesScales& scales);

// A reversal-threshold coordinate (model::SearchCoordinate::Kind::kReversalThreshold, in
// threshold / stroke): the fitness is flat in it between two reversal amplitudes and jumps at
// each, which a swarm cannot see. These are the points to try from `fit`: its other coordinates
// with coordinate `index` just inside each distinct reversal amplitude within [lower, upper]
// (at most `count`, spread by rank), and `fit` itself.
std::vector<Point> reversal_threshold_trials(const FitSeries& series, const SeriesScales& scales, const Point& fit,
                                             Eigen::Index index, double lower = 0.3, double upper = 1.0,
                                             std::size_t count = 24);

// Whether the effect has such a coordinate.
bool has_reversal_threshold(const model::EffectInfo& effect);
// The extreme |x| of each stretch of travel in one direction that ends with a travel back of at
// least 1 % of the stroke (the noise cannot make one), ascending [m].
std::vector<double> reversal_amplitudes(const FitSeries& series, const SeriesScales& scales);
// The fit from `theta` with each reversal-threshold coordinate chosen among the trials above:
// coarse by rank over every reversal, then every reversal between the best coarse one's
// neighbours. Adds the observer passes it spent to `evaluations`.
FittedModel scan_reversal_thresholds(const model::EffectInfo& effect, const ParameterSpace& space,
                                     const FitSeries& series, const SeriesScales& scales, const Point& theta,
                                     std::int64_t& evaluations);

}  // namespace mrd::tools
