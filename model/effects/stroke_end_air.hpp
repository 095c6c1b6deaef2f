#pragma once

#include "common/validation_report.hpp"

namespace mrd::model {

// The paper's Section 4.3: when the piston reverses near the end of its stroke (30-40 mm on the
// MRD-SEU-D050) it first compresses air drawn into the chamber, and the damping force is about
// zero until the air is compressed; then it builds up again. Model: after a reversal at
// |x_rev| > threshold, the fluid force is scaled by
//   f = 1 - depth exp(-s / length),   s = |x - x_rev| the travel since that reversal,
// and by 1 after any reversal inside the threshold. `depth` near 1 is the paper's "force 0";
// `length` sets how much travel the recovery takes. The gas spring is not scaled: the
// accumulator's pressure acts on the rod whatever the chamber holds.
struct StrokeEndAirParams {
  bool enabled = false;
  double threshold = 0.030;        // |x| at the reversal beyond which air was drawn in [m]
  double depth = 0.9;              // fraction of the force lost at the reversal [-], in [0, 1]
  double length = 5e-3;            // e-folding travel of the recovery [m]
  double reversal_travel = 1e-4;   // travel back from an extreme that confirms a reversal [m]
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
  double reversal_travel_;
  bool started_ = false;
  int direction_ = 0;         // +1 moving up, -1 down, 0 not known yet
  double extreme_ = 0.0;      // furthest point in the present direction [m]
  double reversal_ = 0.0;     // where the last reversal was [m]
  bool armed_ = false;
  long reversals_ = 0;
  double factor_ = 1.0;
};

}  // namespace mrd::model
