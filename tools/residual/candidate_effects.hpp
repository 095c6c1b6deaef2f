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
  bool current_varies = false;  // tools::current_varies(series)
  bool current_steps = false;   // within a run: fast changes, so a coil lag shows
};
SeriesScales series_scales(const FitSeries& series);

// The base model's free parameters, set on `origin` (the config's damper, or the default), each
// inside its documented physical range (docs/CLOSING-THE-LOOP.md, "The base fit"):
//   log10 of the field gain N / Le [turns/m] (Eq. 9), within 1.5 decades of the starting coil's;
//   the J-A material's shape (Eq. 1-10): log10 k / a, c and alpha Ms / (3 a);
//   Eq. 13's exponent of B;
//   log10 of the sign velocity v_s [m/s] and the sign shape (Eq. 11's regularised sgn);
//   the Herschel-Bulkley flow index n of the viscous term.
// The force scale, viscous coefficient and seal friction are the linear terms. From a force
// record only the material's shape is identifiable: a is tied to the field gain (only H / a
// enters) and Ms to the force scale (B ~ mu0 Ms at the knee); both keep the origin's values.
// What a run determines decides which coordinates are free (Magnetics): the field and the
// material only when the current varies; with kKept every point shares the origin's B.
enum class Magnetics {
  kMaterial,  // the field gain and the J-A material's shape
  kGain,      // the field gain alone
  kKept,      // neither: the origin's B
};
ParameterSpace base_space(const model::DamperModel& origin, const model::DamperModel& start,
                          const SeriesScales& scales, Magnetics magnetics = Magnetics::kGain);
// The base coordinates of `model` in that space.
Point base_coordinates(const model::DamperModel& model, const model::DamperModel& start,
                       const SeriesScales& scales, Magnetics magnetics = Magnetics::kGain);
// The base coordinates of `model` on (or past) the edge of their physical range, one line each
// ("J-A c at the edge of its physical range [0.01, 0.95]"): the run asks for more than the range
// allows. The ceiling's top is no ceiling at all (Eq. 13's plain law), so it is no edge. With
// `unphysical_only`, edges that are a member of the family (the sign shape's atan and knee, the
// ceiling's slow and corner shapes, no mean field) are left out.
std::vector<std::string> base_coordinates_at_edge(const model::DamperModel& model, const model::DamperModel& start,
                                                  const SeriesScales& scales, Magnetics magnetics = Magnetics::kGain,
                                                  bool unphysical_only = false);
// What base_space frees for this run: kept fields stay kept.
Magnetics free_magnetics(const SeriesScales& scales, Magnetics wanted);

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
