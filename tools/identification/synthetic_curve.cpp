#include "tools/identification/synthetic_curve.hpp"

#include <cmath>

#include "tools/identification/loop_simulation.hpp"

namespace mrd::tools {

BHCurve synthetic_loop(const model::JilesAthertonParams& params, double H_max, std::size_t points,
                       const model::JilesAthertonSettings& settings) {
  BHLoop loop;
  for (std::size_t i = 0; i < points; ++i) {
    const double phase = static_cast<double>(i) / static_cast<double>(points);  // [0, 1)
    loop.H.push_back(H_max * (phase < 0.5 ? 1.0 - 4.0 * phase : 4.0 * phase - 3.0));
  }
  loop.B.assign(points, 0.0);
  BHCurve curve{"synthetic", {loop}};
  LoopSimulator(curve).simulate(params, curve.loops.front().B, settings);
  return curve;
}

}  // namespace mrd::tools
