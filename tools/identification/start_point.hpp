#pragma once

#include <array>
#include <string>

#include "tools/identification/bh_curve.hpp"
#include "tools/identification/bh_objective.hpp"
#include "tools/optimisation/optimiser.hpp"

namespace mrd::tools {

// What the start-point estimate read off the largest loop, for the report.
struct LoopFeatures {
  double H_tip = 0.0;         // [A/m]
  double M_tip = 0.0;         // magnetisation at the tip [A/m]
  double coercive_field = 0.0;  // [A/m]
  double remanence = 0.0;     // M at H = 0 [A/m]
  double chi_origin = 0.0;    // slope of the loop's mid-line at H = 0
  double chi_reversal = 0.0;  // slope just after the tip, where only reversible change acts
};

LoopFeatures measure_largest_loop(const BHCurve& curve);

// A J-A start point from the loops alone (docs/IDENTIFICATION.md, "Start point"):
//  Ms, a, alpha: the loop's mid-line stands in for the anhysteretic curve. Its slope at the
//    origin fixes Ms/(3a - alpha Ms), its tip fixes Ms L((H+alpha M)/a); Ms is then the value
//    whose curve fits the mid-line best.
//  k: the coercive field.
//  c: the reversible slope just after the tip over the anhysteretic slope there (Eq. 2).
Point estimate_start_point(const BHCurve& curve);

// For each parameter, whether x sits on a face of `bounds` that is a guess, not physics: an
// estimate that was too tight. (Physical faces: alpha = 0, c = 0, c -> 1, and the near-zero
// floors of Ms, a, k.)
std::array<bool, kParameterCount> on_estimated_face(const Point& x, const Bounds& bounds,
                                                    const Point& start);

// The paper's search space: +-100% around the start point. Zero is outside physics for Ms, a
// and k, so their lower bound is 1% of the start; c stays below 1.
Bounds bounds_around(const Point& start, double fraction = 1.0);

}  // namespace mrd::tools
