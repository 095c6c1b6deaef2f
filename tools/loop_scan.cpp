#include "tools/loop_scan.hpp"

#include <cmath>
#include <algorithm>
#include <numbers>

namespace mrd::tools {

LoopScanRow scan_loop(const model::JilesAthertonParams& params, double H_max,
                      int samples_per_cycle, const model::JilesAthertonSettings& settings) {
  // Unit circuit: the field is the input.
  model::JilesAtherton core(params, model::MagneticCircuit{1.0, 1.0}, settings);
  LoopScanRow row;
  row.H_max = H_max;
  double B_end_cycle2 = 0.0;
  std::uint64_t guards_before = 0;
  const int quarter = samples_per_cycle / 4;
  for (int cycle = 0; cycle < 3; ++cycle) {
    if (cycle == 1) guards_before = core.guard_events();
    for (int i = 1; i <= samples_per_cycle; ++i) {
      const double phase = 2.0 * std::numbers::pi * i / samples_per_cycle;
      const double B = core.apply_field(H_max * std::sin(phase));
      if (cycle == 2 && i == quarter) row.B_max = B;
      if (cycle == 2 && i == 2 * quarter) row.remanence = B;
      if (cycle == 2 && i == 3 * quarter) row.symmetry_error = std::fabs(row.B_max + B);
    }
    if (cycle == 1) B_end_cycle2 = core.B();
  }
  row.closure_error = std::fabs(core.B() - B_end_cycle2);
  row.guard_events = core.guard_events() - guards_before;
  return row;
}

std::vector<LoopScanRow> scan_loops(const model::JilesAthertonParams& params,
                                    const std::vector<double>& amplitudes,
                                    const model::JilesAthertonSettings& settings) {
  std::vector<LoopScanRow> rows;
  rows.reserve(amplitudes.size());
  for (const double H_max : amplitudes) rows.push_back(scan_loop(params, H_max, 2000, settings));
  return rows;
}

}  // namespace mrd::tools

namespace mrd::tools {

double max_B_difference(const model::JilesAthertonParams& params, double H_max, int n,
                        const model::JilesAthertonSettings& a,
                        const model::JilesAthertonSettings& b) {
  model::JilesAtherton core_a(params, model::MagneticCircuit{1.0, 1.0}, a);
  model::JilesAtherton core_b(params, model::MagneticCircuit{1.0, 1.0}, b);
  double difference = 0.0;
  for (int i = 1; i <= 2 * n; ++i) {
    const double H = H_max * std::sin(2.0 * std::numbers::pi * i / n);
    difference = std::max(difference, std::fabs(core_a.apply_field(H) - core_b.apply_field(H)));
  }
  return difference;
}

double integrator_error(const model::JilesAthertonParams& params, double H_max, int n,
                        const model::JilesAthertonSettings& settings, double refinement) {
  model::JilesAthertonSettings fine = settings;
  fine.integrator = model::Integrator::kRk4;
  fine.langevin = model::LangevinEvaluation::kExact;
  fine.max_field_step_fraction /= refinement;
  fine.max_substeps = 1 << 22;
  return max_B_difference(params, H_max, n, settings, fine);
}

}  // namespace mrd::tools
