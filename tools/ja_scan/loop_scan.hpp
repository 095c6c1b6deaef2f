#pragma once

#include <vector>

#include "model/jiles_atherton.hpp"

namespace mrd::tools {

// One symmetric major loop at field amplitude Hmax, driven as a sampled sine.
struct LoopScanRow {
  double H_max = 0.0;            // [A/m]
  double B_max = 0.0;            // B at +Hmax on the last cycle [T]
  double remanence = 0.0;        // B at H = 0 on the falling branch [T]
  double closure_error = 0.0;    // |B(end of cycle 3) - B(end of cycle 2)| [T]
  double symmetry_error = 0.0;   // |B(+Hmax) + B(-Hmax)| on the last cycle [T]
  std::uint64_t guard_events = 0;  // runaway of Eq. 10 detected on the last two cycles
  [[nodiscard]] bool physical() const { return guard_events == 0; }
};

// Runs three cycles of H = Hmax sin(2 pi t) from the demagnetised state, with
// `samples_per_cycle` samples, and measures the last ones.
LoopScanRow scan_loop(const model::JilesAthertonParams& params, double H_max,
                      int samples_per_cycle = 2000,
                      const model::JilesAthertonSettings& settings = {});

std::vector<LoopScanRow> scan_loops(const model::JilesAthertonParams& params,
                                    const std::vector<double>& amplitudes,
                                    const model::JilesAthertonSettings& settings = {});

}  // namespace mrd::tools

namespace mrd::tools {

// Max |B_a - B_b| [T] over two cycles of H = Hmax sin(2 pi i / n), from the demagnetised state.
double max_B_difference(const model::JilesAthertonParams& params, double H_max, int n,
                        const model::JilesAthertonSettings& a,
                        const model::JilesAthertonSettings& b);

// max_B_difference against a reference that uses RK4 with 1/refinement of the sub-step size
// and the exact Langevin function: the integrator error figure of docs/MODEL.md.
double integrator_error(const model::JilesAthertonParams& params, double H_max, int n,
                        const model::JilesAthertonSettings& settings, double refinement = 100.0);

// mrd-ja-scan's two tables on stdout: the loops at `points` log-spaced amplitudes from `from`
// to `to` [A/m], and (--integrator-error) RK4's and Heun's error and the tabulated Langevin
// function's change at three sub-step fractions, two amplitudes and two sample counts.
void print_loop_scan(const model::JilesAthertonParams& p, double from, double to, int points);
void print_integrator_errors(const model::JilesAthertonParams& p);

}  // namespace mrd::tools
