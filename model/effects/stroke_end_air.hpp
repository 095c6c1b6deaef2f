#pragma once

#include <cmath>
#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include "common/validation_report.hpp"
#include "model/effects/effect_traits.hpp"

namespace mrd::model {

// The paper's Section 4.3: when the piston reverses near the end of its stroke (30-40 mm on the
// MRD-SEU-D050) it first compresses air drawn into the chamber, and the damping force is about
// zero until the air is compressed; then it builds up again. How it builds up depends on the
// air's volume and the valve, so the model leaves the shape free: after a reversal at
// |x_rev| > threshold, the fluid force is scaled by
//   f = 1 - depth                                  for s < dead_travel (air being compressed),
//   f = 1 - depth [(1 - r) exp(-u / length) + r max(0, 1 - u / length)]  after it, u = s - dead_travel,
// s = |x - x_rev| the travel since that reversal, r the ramp share (0: an exponential recovery,
// 1: a linear ramp over `length`), and f = 1 after any reversal inside the threshold. `depth`
// near 1 is the paper's "force 0". The gas spring is not scaled: the accumulator's pressure
// acts on the rod whatever the chamber holds.
struct StrokeEndAirParams {
  bool enabled = false;
  double threshold = 0.030;        // |x| at the reversal beyond which air was drawn in [m]
  double depth = 0.9;              // fraction of the force lost at the reversal [-], in [0, 1]
  double length = 5e-3;            // recovery travel: e-folding (exponential) or full (ramp) [m]
  double dead_travel = 0.0;        // travel after the reversal before the force recovers at all [m]
  double ramp_share = 0.0;         // r: 0 exponential recovery, 1 linear ramp, between a blend [-]
  double reversal_travel = 1e-4;   // travel back from an extreme that confirms a reversal [m]

  bool operator==(const StrokeEndAirParams&) const = default;
};

ValidationReport validate(const StrokeEndAirParams& params);

// Reversals are found on the displacement, not on the sign of a velocity estimate: a noisy
// velocity near zero would flip many times and re-arm the collapse each time. A reversal is
// confirmed once the piston has come back `reversal_travel` from its extreme (above the LVDT
// noise); s is then counted from the extreme itself, so f steps from 1 to about 1 - depth at
// the confirmation. (A collapse ramped in over that travel, continuous in x, was tried: on a
// noisy LVDT the running extreme sits a noise excursion above x near every extreme, so the
// ramp fires early and the observer's error grew by a third.) No heap, no exceptions; a
// non-finite x is ignored.
class StrokeEndAir {
 public:
  explicit StrokeEndAir(const StrokeEndAirParams& params);

  // Takes the displacement [m]; returns the force factor f.
  double step(double displacement);
  [[nodiscard]] double factor() const { return factor_; }
  [[nodiscard]] bool armed() const { return armed_; }  // the last reversal was beyond the threshold
  [[nodiscard]] long reversals() const { return reversals_; }  // confirmed since the start
  void reset();

 private:
  double threshold_;
  double depth_;
  double inv_length_;
  double dead_travel_;
  double ramp_share_;
  double reversal_travel_;
  bool started_ = false;
  int direction_ = 0;         // +1 moving up, -1 down, 0 not known yet
  double extreme_ = 0.0;      // furthest point in the present direction [m]
  double reversal_ = 0.0;     // where the last reversal was [m]
  bool armed_ = false;
  long reversals_ = 0;
  double factor_ = 1.0;
};

// The descriptor (effect_traits.hpp).
struct StrokeEndAirEffect : EffectTraitsBase<StrokeEndAirParams> {
  using Element = StrokeEndAir;
  static constexpr std::string_view kName = "stroke_end_air";
  static constexpr std::string_view kSeparatedBy =
      "reversals both inside and beyond the stroke-end threshold (the air acts only after those beyond)";
  // Hook (effect_chain.hpp): a factor on the fluid force.
  static double force_factor(Element& e, double displacement) { return e.step(displacement); }

  template <typename Visitor>
  static void fields(Params& p, Visitor&& v) {
    v("enabled", p.enabled);
    v("threshold", p.threshold);
    v("depth", p.depth);
    v("length", p.length);
    v("dead_travel", p.dead_travel);
    v("ramp_share", p.ramp_share);
    v("reversal_travel", p.reversal_travel);
  }

  static constexpr std::array kSearch = {
      SearchCoordinate{"threshold / stroke", [](const RunScales&) { return 0.3; },
                       [](const RunScales&) { return 0.98; }, SearchCoordinate::Kind::kReversalThreshold},
      SearchCoordinate{"depth", [](const RunScales&) { return 0.0; }, [](const RunScales&) { return 0.95; }},
      SearchCoordinate{"log10 length / stroke", [](const RunScales&) { return -2.5; },
                       [](const RunScales&) { return -0.5; }},
      SearchCoordinate{"dead travel / stroke", [](const RunScales&) { return 0.0; },
                       [](const RunScales&) { return 0.2; }},
      SearchCoordinate{"ramp share", [](const RunScales&) { return 0.0; }, [](const RunScales&) { return 1.0; }}};
  static void apply(Params& p, std::span<const double> x, const RunScales& s) {
    p.enabled = true;
    p.threshold = x[0] * s.stroke;
    p.depth = x[1];
    p.length = std::pow(10.0, x[2]) * s.stroke;
    p.dead_travel = x[3] * s.stroke;
    p.ramp_share = x[4];
    p.reversal_travel = std::min(1e-4, 0.01 * s.stroke);
  }
  static void coordinates(const Params& p, const RunScales& s, std::span<double> x) {
    x[0] = p.threshold / s.stroke;
    x[1] = p.depth;
    x[2] = std::log10(p.length / s.stroke);
    x[3] = p.dead_travel / s.stroke;
    x[4] = p.ramp_share;
  }
  static std::optional<std::string> implausible(const Params& p, const RunScales&);
  template <typename Visitor>
  static void report(const Params& p, Visitor&& v) {
    v("threshold_m", p.threshold);
    v("depth", p.depth);
    v("length_m", p.length);
    v("dead_travel_m", p.dead_travel);
    v("ramp_share", p.ramp_share);
  }
  static Params nominal(DamperClassId damper) {
    // From three quarters of the class's stroke amplitude (Section 4.3: 30-40 mm of 40 mm).
    Params p;
    p.threshold = damper == DamperClassId::k50kN ? 0.030 : 0.015;
    p.length = damper == DamperClassId::k50kN ? 5e-3 : 2.5e-3;
    p.depth = 0.45;
    return p;
  }
  static void resize(Params& p, double size, double /*dissipated_energy*/) {
    p.enabled = true;
    p.depth = std::min(size * p.depth, 0.95);
  }
  static std::string size_summary(const Params& p);
};
}  // namespace mrd::model
