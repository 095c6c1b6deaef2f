#pragma once

#include <cstdint>

#include "tools/optimisation/optimiser.hpp"

namespace mrd::tools {

// Classical PSO, Eq. 14, with a constant inertia. The defaults are the usual constriction
// equivalent (w = 0.7298, c1 = c2 = 1.4962, Clerc and Kennedy 2002).
struct ClassicalPsoSettings {
  double w = 0.7298;
  double c1 = 1.4962;
  double c2 = 1.4962;
  double velocity_limit = 0.2;  // |v_j| <= this fraction of the range of x_j
};

// The paper's improved PSO (Section 3.2); see docs/IDENTIFICATION.md for how the three
// additions are put together inside the evaluation budget.
struct ImprovedPsoSettings {
  double w_max = 0.8;  // Eq. 16
  double w_min = 0.2;
  double c1 = 2.0;     // Section 4.1
  double c2 = 2.0;
  double velocity_limit = 0.1;
  double F = 0.4;         // Eq. 18 scaling factor
  double F_spread = 0.5;  // > 0: each trial draws F uniformly from [F, F + F_spread] (dither)
  double CR = 0.95;       // Eq. 19 crossover probability
  // Stall detector: the global best improved by less than stall_tolerance (relative) for
  // stall_iterations iterations in a row. Then cauchy_trials points are drawn by Eq. 22.
  int stall_iterations = 5;
  double stall_tolerance = 1e-4;
  int cauchy_trials = 2;
  double cauchy_scale = 0.01;
};

OptimisationResult run_classical_pso(BatchObjective& objective, const Bounds& bounds,
                                     const Budget& budget, const ClassicalPsoSettings& settings,
                                     std::uint64_t seed);

OptimisationResult run_improved_pso(BatchObjective& objective, const Bounds& bounds,
                                    const Budget& budget, const ImprovedPsoSettings& settings,
                                    std::uint64_t seed);

}  // namespace mrd::tools
