#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/damper_model.hpp"
#include "tools/residual/fit_series.hpp"
#include "tools/residual/model_fit.hpp"

namespace mrd::tools {

// What the searches need to know of the series to set their ranges.
struct SeriesScales {
  double sample_period = 0.0;      // [s]
  double duration = 0.0;           // of the longest run [s]
  double stroke = 0.0;             // 99.9th percentile of |x| [m]
  double speed = 0.0;              // 99th percentile of |v| [m/s]
  double dissipated_energy = 0.0;  // sum of max(F v, 0) dt over the longest run [J]
  bool current_varies = false;     // over the series, more than 5 % of its largest |value|
  bool current_steps = false;      // within a run: fast changes, so a coil lag shows
  bool measured_temperature = false;
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

// The field gain alone, the rest of `origin` kept (its gas spring's F0 + k x refitted among the
// linear terms when it has one): the magnetic step of a refinement that otherwise shares B.
ParameterSpace field_gain_space(const model::DamperModel& origin, const model::DamperModel& start);

// Whether the effect changes the gap induction B for a given current (only a coil lag does):
// such an effect moves what the field gain absorbed, and its trials cannot share a B trace.
bool changes_induction(std::string_view effect);

// The candidate effect `name` (model::kEffectNames) added to `model`, over the parameters
// identifiable from a run (docs/CLOSING-THE-LOOP.md lists them and their ranges).
ParameterSpace effect_space(const std::string& name, const model::DamperModel& model,
                            const SeriesScales& scales);

// The coordinates of the effect `name` of `model` in effect_space(name, ...): where a joint
// refinement of effects already accepted starts.
Point effect_coordinates(const std::string& name, const model::DamperModel& model, const SeriesScales& scales);

// stroke_end_air's fitness is flat in the threshold between two reversal amplitudes and jumps
// at each, which a swarm cannot see. These are the points to try from `fit`: its other
// coordinates with the threshold just inside each distinct reversal amplitude within
// [lower, upper] (in threshold / stroke; at most `count`, spread by rank), and `fit` itself.
std::vector<Point> stroke_threshold_trials(const FitSeries& series, const SeriesScales& scales, const Point& fit,
                                           double lower = 0.3, double upper = 1.0, std::size_t count = 24);

// The stroke_end_air fit from `theta` with the threshold chosen among the trials above: coarse
// by rank over every reversal, then every reversal between the best coarse one's neighbours.
// Adds the observer passes it spent to `evaluations`.
FittedModel scan_stroke_threshold(const ParameterSpace& space, const FitSeries& series, const SeriesScales& scales,
                                  const Point& theta, std::int64_t& evaluations);

// Why a fitted effect is not a physical, non-trivial instance of itself (negative spring
// stiffness, a lag shorter than a sample, ...); nullopt when it is one.
std::optional<std::string> implausible(const std::string& name, const FittedModel& fit,
                                       const SeriesScales& scales);

// The fitted parameters of the effect, for reports: name -> value in SI.
std::vector<std::pair<std::string, double>> effect_parameters(const std::string& name,
                                                              const model::EffectSet& effects);

}  // namespace mrd::tools
