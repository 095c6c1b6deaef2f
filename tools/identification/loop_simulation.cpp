#include "tools/identification/loop_simulation.hpp"

namespace mrd::tools {

std::vector<double> turning_points(std::span<const double> H) {
  std::vector<double> path;
  if (H.empty()) return path;
  int direction = 0;
  for (std::size_t i = 1; i < H.size(); ++i) {
    const double step = H[i] - H[i - 1];
    const int now = step > 0.0 ? 1 : (step < 0.0 ? -1 : 0);
    if (now == 0) continue;
    if (direction != 0 && now != direction) path.push_back(H[i - 1]);
    direction = now;
  }
  path.push_back(H.back());
  return path;
}

LoopSimulator::LoopSimulator(const BHCurve& curve) {
  for (const auto& loop : curve.loops) {
    LoopRange range{H_.size(), 0, pre_cycle_.size(), 0};
    H_.insert(H_.end(), loop.H.begin(), loop.H.end());
    B_.insert(B_.end(), loop.B.begin(), loop.B.end());
    // Demagnetised -> the first sample -> one lap of turning points -> back to the first
    // sample, where the recorded pass begins.
    pre_cycle_.push_back(loop.H.front());
    for (const double h : turning_points(loop.H)) pre_cycle_.push_back(h);
    pre_cycle_.push_back(loop.H.front());
    range.last = H_.size();
    range.pre_cycle_last = pre_cycle_.size();
    loops_.push_back(range);
  }
}

SimulationStats LoopSimulator::simulate(const model::JilesAthertonParams& params,
                                        std::span<double> B_out,
                                        const model::JilesAthertonSettings& settings,
                                        double cutoff) const {
  SimulationStats stats;
  const model::MagneticCircuit unit_circuit{1.0, 1.0};  // the file gives H directly
  for (const auto& loop : loops_) {
    model::JilesAtherton ja(params, unit_circuit, settings);
    for (std::size_t i = loop.pre_cycle_first; i < loop.pre_cycle_last; ++i) {
      ja.apply_field(pre_cycle_[i]);
    }
    for (std::size_t i = loop.first; i < loop.last; ++i) {
      B_out[i] = ja.apply_field(H_[i]);
      const double e = B_[i] - B_out[i];
      stats.squared_error += e * e;
      if (stats.squared_error > cutoff) {
        stats.abandoned = true;
        break;
      }
    }
    stats.guard_events += ja.guard_events();
    stats.recoveries += ja.recoveries();
    if (stats.abandoned) break;
  }
  return stats;
}

}  // namespace mrd::tools
