#pragma once

#include <cstdint>
#include <initializer_list>
#include <memory>

#include "model/damper_model.hpp"
#include "tools/residual/model_fit.hpp"
#include "tools/residual/search_context.hpp"

namespace mrd::tools::search {

struct RefinePass {
  int evaluations_per_coordinate;
  double step;  // Nelder-Mead's first simplex, as a fraction of each coordinate's range
  // After the pass, Nelder-Mead over the field gain alone with this many evaluations, when the
  // gain is not among the pass's coordinates (0: none).
  int gain_evaluations = 0;
};

// Nelder-Mead over the base coordinates and those of `effects` together (an effect changes
// what the base absorbed), once per pass, each pass from the last one's model, so that its
// linear terms come close to identity and what the search saw is what the observer runs (the
// linear terms scale the viscous force past some effects' factors only approximately). The
// first pass starts on `origin` at `effect_start`; its theta holds the effects' coordinates.
//
// The field gain: an effect that changes B (a coil lag) changes what the gain absorbed, so the
// gain joins its coordinates, as it does whenever the model already has such an effect (it and
// the gain shape B together, and an effect's best fit then moves both). Other effects on such a
// model leave B alone: their trials share one B trace, and the gain is refined on its own
// between passes, since such an effect can still take over force the gain had absorbed (on the
// Table 4 schedule the current follows the displacement, so a spring's k x looks like a field).
// `induction`, when given, is a B trace the first pass may already use.
FittedModel refine_jointly(const Search& s, const model::DamperModel& origin, const Effects& effects,
                           const Point& effect_start, std::initializer_list<RefinePass> passes,
                           std::int64_t& evaluations, std::shared_ptr<const InductionTrace> induction = nullptr);

// The coordinates of every effect of `effects` in `model`, in that order.
Point effect_coordinates(const Effects& effects, const model::DamperModel& model, const SeriesScales& scales);

}  // namespace mrd::tools::search
