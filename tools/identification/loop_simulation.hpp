#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "model/jiles_atherton.hpp"
#include "tools/identification/bh_curve.hpp"

namespace mrd::tools {

struct SimulationStats {
  std::uint64_t guard_events = 0;  // Eq. 10 ran away somewhere (non-physical parameters)
  std::uint64_t recoveries = 0;    // the state went non-finite and was reset
  double squared_error = 0.0;      // sum of (B_measured - B_simulated)^2 [T^2]
  bool abandoned = false;          // stopped early: squared_error already exceeded the cutoff
};

// Plays the measured H of every loop through the J-A model and returns B at each point.
// Each loop starts demagnetised and is driven once through its own turning points before
// the recorded pass, so the loop is compared in its cyclic steady state, as it was measured.
// The model is rate-independent and sub-steps in H, so the pre-cycle may visit only the
// turning points: it integrates on the same grid as a pass through every sample.
class LoopSimulator {
 public:
  explicit LoopSimulator(const BHCurve& curve);

  [[nodiscard]] std::size_t points() const { return H_.size(); }
  [[nodiscard]] std::span<const double> measured_B() const { return B_; }

  // B_out.size() == points(). Allocation-free. The run stops as soon as the squared error
  // passes `cutoff` (an optimiser's candidate that can no longer win needs no more work);
  // then the rest of B_out is left as it was.
  SimulationStats simulate(const model::JilesAthertonParams& params, std::span<double> B_out,
                           const model::JilesAthertonSettings& settings = {},
                           double cutoff = std::numeric_limits<double>::infinity()) const;

 private:
  struct LoopRange {
    std::size_t first, last;                      // [first, last) in H_ and B_
    std::size_t pre_cycle_first, pre_cycle_last;  // [.., ..) in pre_cycle_
  };
  std::vector<double> H_, B_, pre_cycle_;
  std::vector<LoopRange> loops_;
};

// The local extrema of `H` in order, ending with H.back(): the path the pre-cycle follows.
std::vector<double> turning_points(std::span<const double> H);

}  // namespace mrd::tools
