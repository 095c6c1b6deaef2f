#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "tools/residual/fit_series.hpp"

namespace mrd::tools {

// The fits' robust loss (docs/CLOSING-THE-LOOP.md, "Robust fit"): Huber's, by iterative
// reweighting. A sample whose residual lies beyond `tuning` robust sigmas (1.4826 MAD of the
// kept samples' residual) weighs tuning sigma / |r|: its pull on a fit grows linearly, not
// quadratically, so a fault no screening rule names moves the fit little. Gaussian noise
// leaves 0.3 % of the samples beyond three sigmas, and those barely down-weighted (0.02 % of
// the weight taken): a clean run fits as it did.
struct RobustLoss {
  double tuning = 3.0;  // [robust sigmas]
  // The base is refitted with the weights only when they take at least this share of the kept
  // samples' weight away (Gaussian noise takes about 0.02 %).
  double refit_share = 0.002;
};

struct RobustWeights {
  std::vector<double> weight;  // per sample of the series; 1 for excluded samples
  double sigma = 0.0;          // [N], the residual's robust sigma
  // Sum of (1 - w) over the kept samples, over their count, leaving out those settling after a
  // switch of the coil current (FitSeries::after_switch): a switch-on transient the base cannot
  // follow is evidence for an effect (a coil lag), and a robust base would hide it.
  double down_weighted_share = 0.0;
};

RobustWeights huber_weights(const FitSeries& series, const std::vector<double>& predicted,
                            const RobustLoss& loss = {});

// A stretch of samples the robust loss down-weighted most: weight under one half, neighbours
// within `join_s` joined.
struct DownWeightedSpan {
  std::string run;
  double start_s = 0.0;  // the run's own time [s]
  double end_s = 0.0;
  std::size_t samples = 0;
  double lost_weight = 0.0;    // sum of (1 - w): what the loss took from the span
  double peak_residual = 0.0;  // [N], the largest |measured - predicted| in it
};

// At most `most` spans, the heaviest losses first.
std::vector<DownWeightedSpan> down_weighted_spans(const FitSeries& series, const std::vector<double>& predicted,
                                                  const RobustWeights& weights, std::size_t most = 5,
                                                  double join_s = 0.02);

}  // namespace mrd::tools
