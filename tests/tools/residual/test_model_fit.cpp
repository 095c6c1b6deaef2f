// The fit's building blocks: the linear terms describe a real model exactly, the swarm and
// Nelder-Mead recover a known parameter, and the residual's structure is read correctly.
#include "tools/residual/model_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/typical_ranges.hpp"
#include "tools/residual/candidate_effects.hpp"
#include "tools/residual/residual_structure.hpp"
#include "tests/tools/residual/residual_test_support.hpp"

namespace {

using namespace mrd::tools;

FitSeries table4_series(std::vector<EffectRequest> effects = {}) {
  return make_fit_series({residual_testing::simulated_recorded_run(RunProfile::kTable4, "50kN", std::move(effects), 4.0)}, {});
}

TEST(ModelFit, LinearTermsAreTheModelTheyDescribe) {
  const FitSeries s = table4_series();
  const mrd::model::DamperModel base;
  std::vector<double> f, scaled;
  predict_force(base, s, f);
  // The gas spring's F0 and k are linear columns (its descriptor's kLinear).
  const LinearTerms t{0.37, 2500.0, 0.0, {mrd::model::find_effect("gas_spring")}, {120.0, 4000.0}};
  predict_force(apply_linear_terms(base, t), s, scaled);
  double worst = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double expected =
        t.force_scale * f[i] + t.extra_viscous * s.velocity[i] + 120.0 + 4000.0 * s.displacement[i];
    worst = std::max(worst, std::fabs(scaled[i] - expected));
    largest = std::max(largest, std::fabs(expected));
  }
  EXPECT_LT(worst, 1e-9 * largest);
}

// The same for a Herschel-Bulkley fluid with seal friction: the viscous correction multiplies the
// fluid's own shape c0 v_ref |v / v_ref|^n / c0, written out here from the definition, and the
// friction the sign term; and the fit finds the terms back from a force made that way.
TEST(ModelFit, LinearTermsCarryTheFlowIndexAndTheSealFriction) {
  const FitSeries s = table4_series();
  mrd::model::DamperModel base;
  base.fluid.flow_index = 0.7;
  base.geometry.seal_friction = 50.0;
  std::vector<double> f, scaled;
  predict_force(base, s, f);
  LinearTerms t{0.6, 3000.0, 30.0, {}, {}};
  t.shapes.emplace(base.geometry, base.fluid.viscosity, base.fluid.flow_index);
  predict_force(apply_linear_terms(base, t), s, scaled);
  double worst = 0.0, largest = 0.0;
  std::vector<double> made(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double v = s.velocity[i];
    const double shape = std::copysign(0.1 * std::pow(std::fabs(v) / 0.1, 0.7), v);
    made[i] = 0.6 * f[i] + 3000.0 * shape + 30.0 * std::tanh(v / base.geometry.sign_velocity_scale);
    worst = std::max(worst, std::fabs(scaled[i] - made[i]));
    largest = std::max(largest, std::fabs(made[i]));
  }
  EXPECT_LT(worst, 1e-9 * largest);
  EXPECT_NEAR(apply_linear_terms(base, t).geometry.seal_friction, 0.6 * 50.0 + 30.0, 1e-12);
  FitSeries from_made = s;
  from_made.force = made;
  const LinearTerms back = fit_linear_terms(from_made, f, {}, &base);
  EXPECT_NEAR(back.force_scale, 0.6, 1e-6);
  EXPECT_NEAR(back.extra_viscous, 3000.0, 1e-3);
  EXPECT_NEAR(back.extra_friction, 30.0, 1e-4);
  // A friction the solve would make negative (a F_s + f < 0) is held at 0.
  for (std::size_t i = 0; i < s.size(); ++i) from_made.force[i] = made[i] - 200.0 * std::tanh(s.velocity[i] / 1e-3);
  const LinearTerms held = fit_linear_terms(from_made, f, {}, &base);
  EXPECT_NEAR(held.force_scale * 50.0 + held.extra_friction, 0.0, 1e-9);
}

// A viscous term the solve holds at c0 = 0, applied fit after fit (each refinement starts from the
// last one's model), leaves the viscosity at the least a fluid has, not a share of the one before
// (that ran a bump stop's fit to 1e-108 Pa s); a positive c0 is the one asked for.
TEST(ModelFit, AViscousTermHeldAtZeroStaysAtTheFluidsLeastViscosity) {
  mrd::model::DamperModel m;
  for (int fit = 0; fit < 20; ++fit) {
    const mrd::model::BinghamDamper now(m.geometry, m.fluid.viscosity);
    m = apply_linear_terms(m, LinearTerms{1.0, -now.viscous_coefficient(), 0.0, {}, {}});
  }
  EXPECT_DOUBLE_EQ(m.fluid.viscosity, mrd::model::kTypicalViscosity.lo);
  const double c0_at_floor = mrd::model::BinghamDamper(m.geometry, m.fluid.viscosity).viscous_coefficient();
  const mrd::model::DamperModel back = apply_linear_terms(m, LinearTerms{1.0, 2000.0, 0.0, {}, {}});
  EXPECT_NEAR(mrd::model::BinghamDamper(back.geometry, back.fluid.viscosity).viscous_coefficient(),
              c0_at_floor + 2000.0, 1e-9 * 2000.0);
}

// B from a trace serves a model with the same magnetics (here, more viscosity and a gas
// spring), bit for bit; a changed field gain or coil lag is not served.
TEST(ModelFit, InductionTraceServesOnlyTheSameMagnetics) {
  const FitSeries s = table4_series();
  mrd::model::DamperModel base;
  const InductionTrace trace(base, s);
  mrd::model::DamperModel after_B = base;
  after_B.fluid.viscosity *= 1.3;
  after_B.effects.get<mrd::model::GasSpringEffect>().enabled = true;
  ASSERT_TRUE(trace.serves(after_B));
  std::vector<double> direct, traced;
  predict_force(after_B, s, direct);
  predict_force(after_B, s, traced, &trace);
  EXPECT_EQ(direct, traced);

  mrd::model::DamperModel gain = base;
  gain.circuit.turns *= 1.01;
  EXPECT_FALSE(trace.serves(gain));
  mrd::model::DamperModel lag = base;
  lag.effects.get<mrd::model::CoilLagEffect>().enabled = true;
  EXPECT_FALSE(trace.serves(lag));
  predict_force(gain, s, direct);
  predict_force(gain, s, traced, &trace);  // not served: J-A runs
  EXPECT_EQ(direct, traced);
}

TEST(ModelFit, LinearTermsComeBackFromAScaledForce) {
  const FitSeries truth = table4_series();
  std::vector<double> f;
  predict_force(mrd::model::DamperModel{}, truth, f);
  FitSeries s = truth;
  for (std::size_t i = 0; i < s.size(); ++i) s.force[i] = 0.5 * f[i] - 800.0 * s.velocity[i];
  const LinearTerms t = fit_linear_terms(s, f, {});
  EXPECT_NEAR(t.force_scale, 0.5, 1e-9);
  EXPECT_NEAR(t.extra_viscous, -800.0, 1e-6);
  EXPECT_LT(linear_fit_rms(s, f, t), 1e-6);
}

TEST(ModelFit, SwarmThenNelderMeadFindTheCoilTimeConstant) {
  const FitSeries s = table4_series({{"coil_lag", 1.0}});  // tau 20 ms on the 50 kN class
  const SeriesScales scales = series_scales(s);
  const ParameterSpace space = effect_space(*mrd::model::find_effect("coil_lag"), mrd::model::DamperModel{}, scales);
  WorkerPool pool(2);
  const FittedModel swarm = fit_space(space, s, &pool, 7, 32);
  const FittedModel fit = refine_space(space, s, swarm.theta, 40, 0.02);
  EXPECT_NEAR(fit.model.effects.get<mrd::model::CoilLagEffect>().time_constant, 0.020, 0.001);
  EXPECT_LE(fit.fitting_rms, swarm.fitting_rms + 1e-9);
  EXPECT_LT(fit.fitting_rms, 40.0);  // the load cell's 25 N noise, and little else
}

TEST(ResidualStructure, WhiteNoiseIsWhite) {
  const FitSeries s = table4_series();
  std::mt19937_64 rng(1);
  std::normal_distribution<double> noise(0.0, 30.0);
  std::vector<double> r(s.size());
  for (double& v : r) v = noise(rng);
  const ResidualStructure st = analyse_residual(s, r);
  EXPECT_NEAR(st.noise_floor, 30.0, 2.0);
  EXPECT_NEAR(st.rms, 30.0, 2.0);
  EXPECT_NE(describe(st).find("white, at the noise floor"), std::string::npos) << describe(st);
}

TEST(ResidualStructure, APeriodicComponentAndTheStrokeEndsAreNamed) {
  const FitSeries s = table4_series();
  std::vector<double> periodic(s.size()), ends(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double t = static_cast<double>(i) * s.sample_period;
    periodic[i] = 500.0 * std::sin(2.0 * M_PI * 3.0 * t);
    ends[i] = std::fabs(s.displacement[i]) > 0.036 ? 800.0 : 0.0;
  }
  const std::string p = describe(analyse_residual(s, periodic));
  // 4 s of data: bins of 0.244 Hz, so 3 Hz reads 2.93.
  EXPECT_NE(p.find("a periodic component at 2.93 Hz"), std::string::npos) << p;
  const std::string e = describe(analyse_residual(s, ends));
  EXPECT_NE(e.find("error concentrates at the stroke ends"), std::string::npos) << e;
}

}  // namespace
