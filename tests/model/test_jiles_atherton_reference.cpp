// JilesAtherton against an independent reference: Eq. 10 as the paper writes it, in time, with
// M alone as the state (M_irr from Eq. 1-2), integrated by Boost.Odeint's adaptive
// Dormand-Prince 5(4) at tight tolerance. The model integrates [M, M_irr] over H with its own
// RK4 sub-steps and a tabulated Langevin function; the Langevin function, Eq. 1-4, 9 and 10 are
// written again here from the paper, so that no code is shared.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "model/jiles_atherton.hpp"

namespace ja_reference {

// One material, in the paper's symbols (beta of Eq. 3 is `a`).
struct Material {
  double Ms;     // [A/m]
  double a;      // [A/m]
  double alpha;  // [-]
  double k;      // [A/m]
  double c;      // [-]
  // The textbook form: the pinning acts on M (Man - M) instead of M_irr (docs/MODEL.md).
  bool pins_total = false;
};
// The firmware's default material, and a softer one with a stronger mean field
// (alpha Ms / 3a = 0.78) and narrow loops, where the reversible coupling of Eq. 10 matters.
constexpr Material kDefault{1.3e6, 2000.0, 1e-3, 1500.0, 0.2};
constexpr Material kStrongMeanField{1.6e6, 1100.0, 1.6e-3, 400.0, 0.1};

constexpr double kTurns = 600.0;    // N
constexpr double kLength = 0.06;    // Le [m]
constexpr double kMu0 = 4e-7 * std::numbers::pi;

double field(double current) { return kTurns * current / kLength; }  // Eq. 9

struct LangevinRef {
  long double value;  // L(x) = coth x - 1/x (Eq. 3)
  long double slope;  // L'(x) = 1/x^2 - 1/sinh^2 x
};
// In long double; below |x| = 1e-3 both closed forms cancel, and their series take over.
LangevinRef langevin_ref(long double x) {
  if (std::fabs(x) < 1e-3L) {
    const long double x2 = x * x;
    return {x / 3.0L - x * x2 / 45.0L + 2.0L * x * x2 * x2 / 945.0L,
            1.0L / 3.0L - x2 / 15.0L + 2.0L * x2 * x2 / 189.0L};
  }
  const long double s = std::sinh(x);
  return {1.0L / std::tanh(x) - 1.0L / x, 1.0L / (x * x) - 1.0L / (s * s)};
}

using State = std::array<double, 1>;  // M [A/m]

// dM/dt of Eq. 10 while H moves linearly from H0 at rate dH/dt.
struct Eq10 {
  Material m;
  double H0;
  double dH_dt;

  void operator()(const State& s, State& ds, double t) const {
    const double H = H0 + dH_dt * t;
    const double M = s[0];
    const double delta = dH_dt > 0.0 ? 1.0 : -1.0;
    const LangevinRef L = langevin_ref((H + m.alpha * M) / m.a);  // Eq. 3-4
    const double Man = m.Ms * static_cast<double>(L.value);
    const double dMan_dHe = m.Ms / m.a * static_cast<double>(L.slope);
    const double Mirr = (M - m.c * Man) / (1.0 - m.c);  // Eq. 1-2
    const double gap = m.pins_total ? Man - M : Man - Mirr;
    // Jiles, Thoelke and Devine (1992): the irreversible term vanishes while the field moves
    // M_irr away from Man (domain walls do not move back against the field).
    const double delta_M = delta * gap > 0.0 ? 1.0 : 0.0;
    const double chi_irr = delta_M * gap / (m.k * delta - m.alpha * gap);
    // Eq. 10 with dMan/dt = dMan/dHe (dH/dt + alpha dM/dt), solved for dM/dt.
    ds[0] = ((1.0 - m.c) * chi_irr + m.c * dMan_dHe) * dH_dt / (1.0 - m.c * m.alpha * dMan_dHe);
  }
};

// The reference's M along a current ramp, one unit of time per ramp.
class Reference {
 public:
  Reference(const Material& m, double relative_tolerance) : m_(m), tolerance_(relative_tolerance) {}

  // From current I0 to I1; returns B [T] (Eq. 8).
  double ramp(double I0, double I1) {
    namespace odeint = boost::numeric::odeint;
    const double H0 = field(I0);
    const double H1 = field(I1);
    if (H1 != H0) {
      auto stepper = odeint::make_controlled(tolerance_ * m_.Ms, tolerance_,
                                             odeint::runge_kutta_dopri5<State>());
      odeint::integrate_adaptive(stepper, Eq10{m_, H0, H1 - H0}, M_, 0.0, 1.0, 1e-3);
    }
    return kMu0 * (H1 + M_[0]);
  }

 private:
  Material m_;
  double tolerance_;
  State M_{0.0};  // demagnetised
};

mrd::model::JilesAtherton model_of(const Material& m, const mrd::model::JilesAthertonSettings& settings = {}) {
  return mrd::model::JilesAtherton({m.Ms, m.a, m.alpha, m.k, m.c}, {kTurns, kLength}, settings);
}

// A current history: its turning points, walked in `samples` equal steps between each pair as
// a control loop would (the model takes each step as one apply_current call).
struct History {
  const char* name;
  std::vector<double> turning_points;  // [A], from 0 A demagnetised
};

struct Comparison {
  double max_difference = 0.0;  // max |B_model - B_ref| over every sample [T]
  double peak_B = 0.0;          // [T]
};

// `reference_material` for the reference when it differs from the model's `m` (another form).
Comparison compare(const Material& m, const History& h, const mrd::model::JilesAthertonSettings& settings,
                   int samples, const Material* reference_material = nullptr) {
  auto model = model_of(m, settings);
  Reference reference(reference_material != nullptr ? *reference_material : m, 1e-12);
  Comparison out;
  double I = 0.0;
  for (const double next : h.turning_points) {
    for (int i = 1; i <= samples; ++i) {
      const double I_i = I + (next - I) * i / samples;
      const double I_prev = I + (next - I) * (i - 1) / samples;
      const double B_ref = reference.ramp(I_prev, I_i);
      const double B_model = model.apply_current(I_i);
      out.max_difference = std::max(out.max_difference, std::fabs(B_model - B_ref));
      out.peak_B = std::max(out.peak_B, std::fabs(B_ref));
    }
    I = next;
  }
  // The comparison means something only if the model never leaned on its guards.
  EXPECT_EQ(model.guard_events(), 0u) << h.name;
  EXPECT_EQ(model.recoveries(), 0u) << h.name;
  return out;
}

const std::vector<History>& histories() {
  static const std::vector<History> h{
      // Virgin curve, then two major loops to +-2 A (2e4 A/m, 8 a).
      {"major loop", {2.0, -2.0, 2.0, -2.0, 2.0}},
      // Biased minor loops from the virgin curve and from the descending branch.
      {"minor loops", {1.2, 0.4, 1.2, 0.4, 1.2, -0.3, 0.3, -0.3, 0.3}},
      // A decaying alternation (demagnetisation), then small reversals about a bias.
      {"reversals", {1.5, -1.2, 0.9, -0.6, 0.3, -0.1, 0.05, 0.0, 0.6, 0.58, 0.62, 0.57, 0.63}},
  };
  return h;
}

// The reference itself first: ten times tighter moves it by far less than the bound below.
TEST(JilesAthertonReference, ReferenceConvergesFarBelowTheComparisonBound) {
  for (const auto& h : histories()) {
    Reference tight(kDefault, 1e-12);
    Reference loose(kDefault, 1e-11);
    double I = 0.0;
    double difference = 0.0;
    for (const double next : h.turning_points) {
      difference = std::max(difference, std::fabs(tight.ramp(I, next) - loose.ramp(I, next)));
      I = next;
    }
    EXPECT_LT(difference, 1e-8) << h.name;  // [T]
  }
}

// Sub-steps 100 times finer than the default and the closed-form Langevin function.
mrd::model::JilesAthertonSettings fine_settings() {
  mrd::model::JilesAthertonSettings fine;
  fine.max_field_step_fraction = 0.0025;
  fine.max_substeps = 1 << 20;
  fine.langevin = mrd::model::LangevinEvaluation::kExact;
  return fine;
}

// With sub-steps 100 times finer than the default and the closed-form Langevin function, the
// model's B is the reference's along every history, for both materials, to 1e-7 T (measured:
// 5e-8 T): the model integrates Eq. 10 and nothing else.
TEST(JilesAthertonReference, BFollowsEq10AlongMajorAndMinorLoopsAndReversals) {
  const mrd::model::JilesAthertonSettings fine = fine_settings();
  for (const Material& m : {kDefault, kStrongMeanField}) {
    for (const auto& h : histories()) {
      const Comparison c = compare(m, h, fine, 20);
      EXPECT_LT(c.max_difference, 1e-7) << h.name << ", Ms " << m.Ms;  // [T]
      EXPECT_GT(c.peak_B, 0.1) << h.name;  // the history reached well into the B-H plane
    }
  }
}

// The textbook form of Eq. 10 (the pinning on M) is this model with k / (1 - c): since
// M = (1 - c) M_irr + c Man, Man - M = (1 - c)(Man - M_irr) (docs/MODEL.md). The reference
// integrates the textbook form with the material's k; the model, with k / (1 - c), follows it
// within the same bound on every history, and with k itself it does not (0.01 T or more apart).
TEST(JilesAthertonReference, TheTextbookFormIsThisOneWithKOverOneMinusC) {
  const mrd::model::JilesAthertonSettings fine = fine_settings();
  for (const Material& m : {kDefault, kStrongMeanField}) {
    Material textbook = m;
    textbook.pins_total = true;
    Material rescaled = m;
    rescaled.k = m.k / (1.0 - m.c);
    double apart = 0.0;
    for (const auto& h : histories()) {
      EXPECT_LT(compare(rescaled, h, fine, 20, &textbook).max_difference, 1e-7) << h.name << ", Ms " << m.Ms;
      apart = std::max(apart, compare(m, h, fine, 20, &textbook).max_difference);
    }
    EXPECT_GT(apart, 0.01) << "Ms " << m.Ms;  // [T]
  }
}

// The real-time settings (RK4 sub-steps of a quarter of min(a, k), the tabulated Langevin
// function) on the default material. At 200 calls a ramp (up to 100 A/m a call, the control
// rate's scale) within 1e-5 T (measured 4.8e-6 T). At 20 calls a ramp within 2e-4 T (measured
// 1.4e-4 T): a sub-step that straddles a reversal's kink (the irreversible term switching on)
// drops RK4's order, and near the coercive field, where the loop is steepest, that shows most
// in B (docs/MODEL.md, Integrator).
TEST(JilesAthertonReference, RealTimeSettingsStayWithinTheirErrorBudget) {
  for (const auto& h : histories()) {
    EXPECT_LT(compare(kDefault, h, {}, 200).max_difference, 1e-5) << h.name;  // [T]
    EXPECT_LT(compare(kDefault, h, {}, 20).max_difference, 2e-4) << h.name;   // [T]
  }
}

// Near H = 0 from the demagnetised state M_irr = Man = 0, so Eq. 10 keeps only its reversible
// part: dM/dH = c Man' / (1 - alpha c Man') with Man' = Ms / 3a, that is
// chi_in = c Ms / (3a - alpha c Ms). Jiles, Thoelke and Devine (1992) give c Ms / 3a, the same
// without the mean field; the model must give the coupled form (4.5 % above it here).
TEST(JilesAthertonReference, InitialSlopeIsTheAnalyticInitialSusceptibility) {
  for (const Material& m : {kDefault, kStrongMeanField}) {
    const double chi_in = m.c * m.Ms / (3.0 * m.a - m.alpha * m.c * m.Ms);
    for (const double direction : {1.0, -1.0}) {
      auto model = model_of(m);
      // The slope grows as chi_irr builds up, by about (1 - c) (Ms / 3a) H / 2k: at 1e-4 A/m
      // that is near 1e-6 of chi_in.
      const double H = direction * 1e-4;
      model.apply_field(H);
      EXPECT_NEAR(model.M() / H, chi_in, 1e-5 * chi_in) << "Ms " << m.Ms << ", direction " << direction;
      EXPECT_EQ(model.recoveries(), 0u);
    }
  }
}


// A material near the fold (alpha Ms / 3a = 0.85, the edge mrd-residual searches to): its
// anhysteretic curve bends over a(1 - alpha Ms / 3a) = 300 A/m of H, not over a = 2000 A/m.
constexpr Material kNearFold{1.3e6, 2000.0, 0.85 * 3.0 * 2000.0 / 1.3e6, 3600.0, 0.95};

// The real-time settings on it, each leg one current step (a switched coil, as on a telegraph
// run), forty times back and forth, within 1e-4 T of the reference (measured 3.8e-5 T of a
// 0.72 T peak). Sub-steps of a quarter of min(a, k), blind to the mean field, drifted 0.047 T
// off, and a fit could lean on that error (mrd-residual once reported a base at 11 kN RMS whose
// search had judged it at 1.1 kN).
TEST(JilesAthertonReference, RealTimeSettingsResolveAStrongMeanFieldOnCurrentSteps) {
  History steps{"current steps", {}};
  for (int i = 0; i < 40; ++i) steps.turning_points.insert(steps.turning_points.end(), {0.085, 0.0});
  const Comparison c = compare(kNearFold, steps, {}, 1);
  EXPECT_LT(c.max_difference, 1e-4);  // [T]
  EXPECT_GT(c.peak_B, 0.5);
}

// Sub-steps the model takes along a history walked as compare() walks it.
std::uint64_t substeps_along(const Material& m, const History& h, const mrd::model::JilesAthertonSettings& settings,
                             int samples) {
  auto model = model_of(m, settings);
  double I = 0.0;
  for (const double next : h.turning_points) {
    for (int i = 1; i <= samples; ++i) model.apply_current(I + (next - I) * i / samples);
    I = next;
  }
  return model.substeps();
}

// The searches' setting (mrd-residual: sub-steps that may grow to 2 % of |He|) on jumps deep
// into saturation, to 100 a and back, 20 calls a leg: within the uniform grid's own error of
// the reference on the default material, within 1e-4 T on a strong mean field, for a fraction
// of the grid's sub-steps.
TEST(JilesAthertonReference, GrowingSubStepsStayNearTheGridDeepInSaturation) {
  const History deep{"deep saturation", {20.0, -20.0, 20.0, 1.0, 20.0}};
  mrd::model::JilesAthertonSettings growing;
  growing.field_step_growth = 0.02;
  for (const Material& m : {kDefault, kStrongMeanField}) {
    const double grid_error = compare(m, deep, {}, 20).max_difference;
    const double growing_error = compare(m, deep, growing, 20).max_difference;
    const std::uint64_t grid_steps = substeps_along(m, deep, {}, 20);
    const std::uint64_t growing_steps = substeps_along(m, deep, growing, 20);
    // Measured: 6.2e-6 T against 6.4e-6 T with 3,740 and 1,545 sub-steps (the default
    // material); within 25 %, as the long steps' rounding differs between builds (1.04x in
    // release, 1.19x in the ASan build's -O1). The strong mean field's grid is finer (a quarter
    // of a (1 - alpha Ms/3a)): 1.1e-5 T in 22,460 sub-steps against 8.2e-5 T in 2,101. Growth
    // steps blind to the mean field cost that; shortened by (1 - alpha Ms/3a) they would
    // overrun the swarms' cap of sub-steps (BaseFit.TheSwarmsCappedSubStepsKeepBOnTheGrid...).
    EXPECT_LT(growing_error, std::max(1.25 * grid_error, 1e-4)) << "Ms " << m.Ms;
    EXPECT_LT(2 * growing_steps, grid_steps) << "Ms " << m.Ms;
  }
}

}  // namespace ja_reference
