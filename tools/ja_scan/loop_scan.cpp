#include "tools/ja_scan/loop_scan.hpp"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <numbers>
#include <vector>

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

void print_loop_scan(const model::JilesAthertonParams& p, double from, double to, int points) {
  std::vector<double> amplitudes;
  for (int i = 0; i < points; ++i) {
    amplitudes.push_back(from * std::pow(to / from, static_cast<double>(i) / (points - 1)));
  }
  std::printf("Ms=%g a=%g alpha=%g k=%g c=%g  alpha*Ms/(3a)=%.3f\n", p.Ms, p.a, p.alpha, p.k, p.c,
              p.mean_field_gain());
  std::printf("%12s %10s %12s %12s %12s %8s %s\n", "Hmax[A/m]", "Bmax[T]", "Br[T]",
              "closure[T]", "symmetry[T]", "guards", "verdict");
  for (const auto& row : scan_loops(p, amplitudes)) {
    std::printf("%12.4g %10.4f %12.4g %12.3g %12.3g %8llu %s\n", row.H_max, row.B_max,
                row.remanence, row.closure_error, row.symmetry_error,
                static_cast<unsigned long long>(row.guard_events),
                row.physical() ? "physical" : "RUNAWAY");
  }
}

void print_integrator_errors(const model::JilesAthertonParams& p) {
  std::printf("max |B - B_ref| [T], 2 cycles of Hmax sin, reference = RK4 at 1/100 sub-step\n"
              "with the exact Langevin function. L table: max |B| change of the tabulated\n"
              "Langevin function (the default) against the exact one, both RK4.\n");
  std::printf("%10s %8s %8s %12s %12s %12s\n", "Hmax", "samples", "fraction", "RK4", "Heun",
              "L table");
  for (const double H_max : {3e3, 2e4}) {
    for (const int n : {50, 1000}) {
      for (const double fraction : {1.0, 0.25, 0.05}) {
        model::JilesAthertonSettings rk4, heun, exact;
        rk4.max_field_step_fraction = heun.max_field_step_fraction = fraction;
        exact.max_field_step_fraction = fraction;
        heun.integrator = model::Integrator::kHeun;
        exact.langevin = model::LangevinEvaluation::kExact;
        std::printf("%10g %8d %8g %12.3g %12.3g %12.3g\n", H_max, n, fraction,
                    integrator_error(p, H_max, n, rk4),
                    integrator_error(p, H_max, n, heun),
                    max_B_difference(p, H_max, n, rk4, exact));
      }
    }
  }
}

}  // namespace mrd::tools
