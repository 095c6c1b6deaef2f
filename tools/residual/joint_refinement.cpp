#include "tools/residual/joint_refinement.hpp"

#include <algorithm>

namespace mrd::tools::search {

FittedModel refine_jointly(const Search& s, const model::DamperModel& origin, const Effects& effects,
                           const Point& effect_start, std::initializer_list<RefinePass> passes,
                           std::int64_t& evaluations, std::shared_ptr<const InductionTrace> induction) {
  const model::DamperModel& start = s.options.start;
  const SeriesScales& scales = s.scales;
  const FitSeries& series = s.fit_series;
  const bool shapes_induction =
      std::ranges::any_of(effects, [](const model::EffectInfo* e) { return e->changes_induction; }) ||
      std::ranges::any_of(model::effect_infos(), [&](const model::EffectInfo& e) {
        return e.changes_induction && e.enabled(origin.effects);
      });
  const Magnetics gain = free_magnetics(scales, shapes_induction ? Magnetics::kGain : Magnetics::kKept);
  FittedModel fit;
  fit.model = origin;
  fit.theta = effect_start;
  for (const RefinePass& pass : passes) {
    ParameterSpace joint = base_space(fit.model, start, scales, gain);
    for (const model::EffectInfo* e : effects) joint = combine(joint, effect_space(*e, fit.model, scales));
    if (gain == Magnetics::kKept) {
      // A new trace only when the gain step moved the magnetics.
      if (!induction || !induction->serves(fit.model))
        induction = std::make_shared<const InductionTrace>(fit.model, series);
      joint.induction = induction;
    }
    const Point base = base_coordinates(fit.model, start, scales, gain);
    Point from(joint.bounds.dimension());
    from << base, fit.theta;
    const auto dimension = static_cast<int>(joint.bounds.dimension());
    fit = refine_space(joint, series, from, 10 + pass.evaluations_per_coordinate * dimension, pass.step);
    evaluations += fit.evaluations;
    fit.theta = fit.theta.tail(fit.theta.size() - base.size()).eval();
    if (gain == Magnetics::kKept && pass.gain_evaluations > 0 && scales.current_varies) {
      const Point effects_theta = fit.theta;
      fit = refine_space(field_gain_space(fit.model, start), series,
                         base_coordinates(fit.model, start, scales, Magnetics::kGain).head(1),
                         pass.gain_evaluations, pass.step);
      evaluations += fit.evaluations;
      fit.theta = effects_theta;
    }
  }
  return fit;
}

Point effect_coordinates(const Effects& effects, const model::DamperModel& model, const SeriesScales& scales) {
  Point all(0);
  for (const model::EffectInfo* e : effects) {
    const Point more = tools::effect_coordinates(*e, model, scales);
    Point both(all.size() + more.size());
    both << all, more;
    all = both;
  }
  return all;
}

}  // namespace mrd::tools::search
