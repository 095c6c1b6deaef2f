#include "model/jiles_atherton.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "model/physical_constants.hpp"

namespace {

using mrd::model::Integrator;
using mrd::model::JilesAtherton;
using mrd::model::JilesAthertonParams;
using mrd::model::JilesAthertonSettings;
using mrd::model::kMu0;
using mrd::model::LangevinEvaluation;
using mrd::model::MagneticCircuit;

const MagneticCircuit kUnitCircuit{1.0, 1.0};  // H equals the "current"

// The equations answered by themselves: no denominator clamped, no non-finite state reset.
// Where a test assumes a sane model, a clamp could otherwise hold its check true.
void expect_unguarded(const JilesAtherton& core) {
  EXPECT_EQ(core.guard_events(), 0u);
  EXPECT_EQ(core.recoveries(), 0u);
}

// B at each sample of `cycles` cycles of H = Hmax sin(2 pi i / n).
std::vector<double> run_loop(JilesAtherton& core, double H_max, int n, int cycles) {
  std::vector<double> B;
  for (int c = 0; c < cycles; ++c) {
    for (int i = 1; i <= n; ++i) {
      B.push_back(core.apply_field(H_max * std::sin(2.0 * std::numbers::pi * i / n)));
    }
  }
  return B;
}

TEST(JilesAtherton, StartsDemagnetisedAndFollowsEq8And9) {
  const MagneticCircuit circuit{600.0, 0.06};
  JilesAtherton core(JilesAthertonParams{}, circuit);
  EXPECT_EQ(core.B(), 0.0);
  core.apply_current(0.3);
  EXPECT_DOUBLE_EQ(core.H(), 600.0 * 0.3 / 0.06);                   // Eq. 9
  EXPECT_DOUBLE_EQ(core.B(), kMu0 * (core.H() + core.M()));          // Eq. 8
  EXPECT_GT(core.M(), 0.0);
}

TEST(JilesAtherton, ApproachesTheAnhystereticCurveAsKGoesToZero) {
  double previous_gap = 1e9;
  for (const double k : {1000.0, 100.0, 10.0, 1.0}) {
    JilesAthertonParams p;
    p.k = k;
    JilesAtherton core(p, kUnitCircuit);
    const int n = 400;
    const auto B = run_loop(core, 2e4, n, 2);
    double gap = 0.0;
    for (int i = n; i < 2 * n; ++i) {  // second cycle only
      const double H = 2e4 * std::sin(2.0 * std::numbers::pi * (i - n + 1) / n);
      gap = std::max(gap, std::fabs(B[i] - kMu0 * (H + core.anhysteretic_magnetisation(H))));
    }
    EXPECT_LT(gap, previous_gap) << "k = " << k;
    EXPECT_EQ(core.recoveries(), 0u) << "k = " << k;
    EXPECT_EQ(core.guard_events(), 0u) << "k = " << k;
    previous_gap = gap;
  }
  EXPECT_LT(previous_gap, 5e-3);  // within 0.3 % of the 1.6 T tip at k = 1 A/m
}

TEST(JilesAtherton, MajorLoopIsSymmetricAndClosesAfterTheFirstCycle) {
  JilesAtherton core(JilesAthertonParams{}, kUnitCircuit);
  const int n = 1000;
  const auto B = run_loop(core, 3e4, n, 3);
  double closure = 0.0;
  double symmetry = 0.0;
  for (int i = 0; i < n; ++i) {
    closure = std::max(closure, std::fabs(B[2 * n + i] - B[n + i]));
    if (i < n / 2) symmetry = std::max(symmetry, std::fabs(B[2 * n + i] + B[2 * n + i + n / 2]));
  }
  EXPECT_LT(closure, 1e-6);
  EXPECT_LT(symmetry, 1e-4);
  expect_unguarded(core);
}

double loop_area(const std::vector<double>& B, double H_max, int n) {
  // Energy lost per cycle per unit volume, the closed integral of H dB [J/m^3].
  double area = 0.0;
  const auto size = static_cast<int>(B.size());
  for (int i = size - n; i < size; ++i) {
    const double H0 = H_max * std::sin(2.0 * std::numbers::pi * (i % n) / n);
    const double H1 = H_max * std::sin(2.0 * std::numbers::pi * (i % n + 1) / n);
    area += 0.5 * (H0 + H1) * (B[i] - B[i - 1]);
  }
  return area;
}

TEST(JilesAtherton, LoopAreaIsPositiveAndGrowsWithK) {
  double previous = 0.0;
  for (const double k : {300.0, 1000.0, 3000.0}) {
    JilesAthertonParams p;
    p.k = k;
    JilesAtherton core(p, kUnitCircuit);
    const auto B = run_loop(core, 2e4, 800, 2);
    const double area = loop_area(B, 2e4, 800);
    EXPECT_GT(area, previous) << "k = " << k;
    expect_unguarded(core);
    previous = area;
  }
  EXPECT_GT(previous, 0.0);
}

// Far past the knee M_irr has caught up with Man, so M is on the anhysteretic curve, here
// Ms (coth x - 1/x) = Ms (1 - 1/x) with x = (H + alpha M)/a > 1e3. The model clamps M to
// [-Ms, Ms], so M <= Ms alone could not fail: from +1e7 to -1e5 A/m in one call (sub-steps
// stretched to 2.5e3 A/m by max_substeps) M ends on the clamp, 260 A/m past the curve. Ramped
// in calls of 1e5 A/m it lands on the curve.
TEST(JilesAtherton, SaturationApproachesTheAnhystereticCurve) {
  JilesAthertonParams p;
  JilesAtherton core(p, kUnitCircuit);
  const auto saturated = [&p](double H, double M) { return p.Ms * (1.0 - p.a / (H + p.alpha * M)); };
  for (int i = 1; i <= 100; ++i) core.apply_field(1e5 * i);
  EXPECT_NEAR(core.M(), saturated(1e7, core.M()), 1e-6 * p.Ms);
  EXPECT_LT(core.M(), p.Ms);
  for (int i = 99; i >= -100; --i) core.apply_field(1e5 * i);
  EXPECT_NEAR(core.M(), -saturated(1e7, -core.M()), 1e-6 * p.Ms);
  EXPECT_GT(core.M(), -p.Ms);
  expect_unguarded(core);
}

TEST(JilesAtherton, NonPhysicalBranchHasNoIrreversibleChange) {
  // Rising field (delta = +1) while M_irr lies above Man: domain walls cannot move back.
  JilesAtherton core(JilesAthertonParams{}, kUnitCircuit);
  const double M_irr = 5e5;
  core.restore({0.0, 0.8 * M_irr, M_irr});
  core.apply_field(50.0);
  EXPECT_EQ(core.state().M_irr, M_irr);
  // Falling field from the same state is the physical direction: M_irr moves down.
  core.restore({0.0, 0.8 * M_irr, M_irr});
  core.apply_field(-50.0);
  EXPECT_LT(core.state().M_irr, M_irr);
}

TEST(JilesAtherton, DenominatorGuardFiresOnlyWhereEq10RunsAway) {
  // Table 1 read as a = 25.3 A/m, alpha = 8.43e-5: alpha*Ms/(3a) = 1.44 (docs/MODEL.md).
  const JilesAthertonParams table1{1.3e6, 25.3, 8.43e-5, 66.6, 0.2};
  JilesAtherton small(table1, kUnitCircuit);
  run_loop(small, 60.0, 2000, 3);
  EXPECT_EQ(small.guard_events(), 0u);

  JilesAtherton large(table1, kUnitCircuit);
  const auto B = run_loop(large, 1000.0, 2000, 3);
  EXPECT_GT(large.guard_events(), 0u);
  EXPECT_EQ(large.recoveries(), 0u);
  for (const double b : B) ASSERT_TRUE(std::isfinite(b));
  EXPECT_LE(std::fabs(large.M()), table1.Ms);

  JilesAtherton well_conditioned(JilesAthertonParams{}, kUnitCircuit);
  run_loop(well_conditioned, 1e5, 2000, 3);
  EXPECT_EQ(well_conditioned.guard_events(), 0u);
}

TEST(JilesAtherton, OneBigCurrentStepIntegratesLikeASlowRamp) {
  const MagneticCircuit circuit{600.0, 0.06};
  JilesAtherton stepped(JilesAthertonParams{}, circuit);
  const double B_step = stepped.apply_current(1.2);  // 0 -> 1.2 A inside one period

  JilesAtherton ramped(JilesAthertonParams{}, circuit);
  for (int i = 1; i <= 10000; ++i) ramped.apply_current(1.2 * i / 10000.0);
  EXPECT_NEAR(B_step, ramped.B(), 1e-6);
  expect_unguarded(stepped);
  expect_unguarded(ramped);

  // Without sub-stepping the same step is far off: the bound is what makes it accurate.
  JilesAthertonSettings one_step;
  one_step.max_substeps = 1;
  JilesAtherton naive(JilesAthertonParams{}, circuit, one_step);
  EXPECT_GT(std::fabs(naive.apply_current(1.2) - ramped.B()), 5e-3);
}

// A random telegraph between 0 and 1.2 A with a few other levels: with jumps recalled within
// 1e-6 Ms, B stays within 0.1 mT of the integrated B at every sample (a search's trial is judged
// on forces a thousand times coarser), most jumps are recalled, and the work falls with them.
// With the tolerance at 0 nothing is recalled and B is the integrated B bit for bit.
TEST(JilesAtherton, RecalledJumpsStayOnTheIntegratedBWithAFractionOfTheWork) {
  const MagneticCircuit circuit{600.0, 0.06};
  JilesAthertonSettings recalling;
  recalling.jump_recall_tolerance = 1e-6;
  JilesAtherton integrated(JilesAthertonParams{}, circuit);
  JilesAtherton recalled(JilesAthertonParams{}, circuit, recalling);
  std::mt19937 rng(7);
  std::bernoulli_distribution flip(0.1);
  double current = 0.0;
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    if (flip(rng)) current = current == 0.0 ? 1.2 : 0.0;
    if (i == 12000) current = 0.7;  // levels never seen: integrated, then kept
    if (i == 12001) current = -0.4;
    worst = std::max(worst, std::fabs(recalled.apply_current(current) - integrated.apply_current(current)));
  }
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(worst, 0.0);  // recalled, not integrated: the match is within the tolerance, not exact
  EXPECT_EQ(integrated.recalled_jumps(), 0u);
  EXPECT_GT(recalled.recalled_jumps(), 1000u);
  EXPECT_LT(recalled.substeps(), integrated.substeps() / 10);
}

// Small moves (a control period's) are never kept or recalled: the work per call stays.
TEST(JilesAtherton, RecalledJumpsLeaveSmallMovesAlone) {
  JilesAthertonSettings recalling;
  recalling.jump_recall_tolerance = 1e-3;
  JilesAtherton core(JilesAthertonParams{}, kUnitCircuit, recalling);
  JilesAtherton reference(JilesAthertonParams{}, kUnitCircuit);
  EXPECT_EQ(run_loop(core, 2e4, 5000, 3), run_loop(reference, 2e4, 5000, 3));
  EXPECT_EQ(core.recalled_jumps(), 0u);
}

double max_loop_difference(const JilesAthertonSettings& a, const JilesAthertonSettings& b) {
  JilesAtherton coarse(JilesAthertonParams{}, kUnitCircuit, a);
  JilesAtherton fine(JilesAthertonParams{}, kUnitCircuit, b);
  const auto Bc = run_loop(coarse, 2e4, 50, 2);
  const auto Bf = run_loop(fine, 2e4, 50, 2);
  double diff = 0.0;
  for (std::size_t i = 0; i < Bc.size(); ++i) diff = std::max(diff, std::fabs(Bc[i] - Bf[i]));
  expect_unguarded(coarse);
  expect_unguarded(fine);
  return diff;
}

TEST(JilesAtherton, Rk4ErrorAgainstA100TimesFinerReference) {
  JilesAthertonSettings reference;
  reference.max_field_step_fraction /= 100.0;
  reference.max_substeps = 1 << 20;
  reference.langevin = LangevinEvaluation::kExact;
  const double rk4 = max_loop_difference(JilesAthertonSettings{}, reference);
  EXPECT_LT(rk4, 1e-5);  // [T]

  JilesAthertonSettings heun;
  heun.integrator = Integrator::kHeun;
  JilesAthertonSettings heun_reference = reference;
  heun_reference.integrator = Integrator::kRk4;
  const double heun_error = max_loop_difference(heun, heun_reference);
  EXPECT_GT(heun_error, rk4);  // the higher order earns its cost
}

// The tabulated Langevin function (model/langevin.hpp) must be invisible next to the
// integrator: docs/MODEL.md budgets 5e-7 T for RK4 at the control rate.
TEST(JilesAtherton, TabulatedLangevinMovesBFarLessThanTheIntegratorError) {
  JilesAthertonSettings exact;
  exact.langevin = LangevinEvaluation::kExact;
  for (const double H_max : {3e3, 2e4, 1e6}) {
    JilesAtherton tabulated_core(JilesAthertonParams{}, kUnitCircuit);
    JilesAtherton exact_core(JilesAthertonParams{}, kUnitCircuit, exact);
    const auto B_tabulated = run_loop(tabulated_core, H_max, 1000, 2);
    const auto B_exact = run_loop(exact_core, H_max, 1000, 2);
    double difference = 0.0;
    for (std::size_t i = 0; i < B_exact.size(); ++i) {
      difference = std::max(difference, std::fabs(B_tabulated[i] - B_exact[i]));
    }
    EXPECT_LT(difference, 1e-11) << H_max;  // [T]; measured about 1e-14
    EXPECT_NEAR(tabulated_core.anhysteretic_magnetisation(H_max),
                exact_core.anhysteretic_magnetisation(H_max), 1e-6);  // [A/m]
    expect_unguarded(tabulated_core);
    expect_unguarded(exact_core);
  }
}

TEST(JilesAtherton, RandomParametersNeverProduceNonFiniteValues) {
  // Documented bounds (docs/MODEL.md): Ms 1e3..3e6 A/m, a and k 1..1e5 A/m, c 0..0.99,
  // alpha 0..2*3a/Ms (mean-field gain up to 2, deep into the runaway region).
  std::mt19937_64 rng(20261121);
  auto log_uniform = [&](double lo, double hi) {
    return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
  };
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  long steps = 0;
  for (int set = 0; set < 200; ++set) {
    JilesAthertonParams p;
    p.Ms = log_uniform(1e3, 3e6);
    p.a = log_uniform(1.0, 1e5);
    p.k = log_uniform(1.0, 1e5);
    p.c = 0.99 * unit(rng);
    p.alpha = 2.0 * 3.0 * p.a / p.Ms * unit(rng);
    JilesAthertonSettings settings;  // both Langevin evaluations, alternately
    settings.langevin = set % 2 == 0 ? LangevinEvaluation::kTabulated : LangevinEvaluation::kExact;
    JilesAtherton core(p, kUnitCircuit, settings);
    const double scale = std::max(p.a, p.k);
    double H = 0.0;
    for (int i = 0; i < 5000; ++i, ++steps) {
      if (unit(rng) < 0.01) {
        H = scale * 50.0 * (2.0 * unit(rng) - 1.0);  // a jump
      } else {
        H += std::min(p.a, p.k) * (2.0 * unit(rng) - 1.0);
      }
      const double B = core.apply_field(H);
      ASSERT_TRUE(std::isfinite(B)) << "set " << set << " step " << i;
      ASSERT_LE(std::fabs(core.M()), p.Ms) << "set " << set << " step " << i;
    }
    // Finite by the equations and their guards, not by resetting a non-finite state.
    ASSERT_EQ(core.recoveries(), 0u) << "set " << set;
  }
  EXPECT_EQ(steps, 1'000'000);
}

}  // namespace
