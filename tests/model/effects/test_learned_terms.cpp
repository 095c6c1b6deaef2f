// The learned terms against their closed forms: each term is its physical law times its
// coefficient, the acceleration is the velocity's backward difference, and the observer adds
// exactly their sum to the base model's force.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "model/effects/effect_set.hpp"
#include "model/observer.hpp"

namespace {

using mrd::model::ForceState;
using mrd::model::LearnedTerm;
using mrd::model::LearnedTerms;
using mrd::model::LearnedTermsEffect;
using mrd::model::LearnedTermsParams;

TEST(LearnedTerms, EachTermIsItsLawTimesItsCoefficient) {
  const ForceState s{.displacement = 0.02, .velocity = -0.3, .acceleration = 0.0, .coil_current = 1.5, .B = 0.8};
  const struct {
    LearnedTerm term;
    double value;
  } expected[] = {{LearnedTerm::kDisplacement, 0.02},
                  {LearnedTerm::kDisplacementCubed, 8e-6},
                  {LearnedTerm::kVelocity, -0.3},
                  {LearnedTerm::kVelocityAbsVelocity, -0.09},
                  {LearnedTerm::kSignVelocity, -1.0},
                  {LearnedTerm::kCurrentVelocity, -0.45},
                  {LearnedTerm::kFieldVelocity, -0.24}};
  for (const auto& e : expected) {
    LearnedTermsParams p;
    p.enabled = true;
    p[e.term] = 7.0;
    LearnedTerms terms(p, 1e-3);
    EXPECT_NEAR(terms.force(s), 7.0 * e.value, 1e-12) << static_cast<int>(e.term);
  }
}

TEST(LearnedTerms, AMassActsOnTheBackwardDifferenceOfTheVelocity) {
  LearnedTermsParams p;
  p.enabled = true;
  p[LearnedTerm::kAcceleration] = 50.0;
  LearnedTerms mass(p, 1e-3);
  EXPECT_EQ(mass.force({.velocity = 0.1}), 0.0);  // no previous sample: no acceleration yet
  // v rising 2 mm/s per 1 ms period: a = 2 m/s^2, F = 100 N.
  EXPECT_NEAR(mass.force({.velocity = 0.102}), 100.0, 1e-9);
  EXPECT_NEAR(mass.force({.velocity = 0.104}), 100.0, 1e-9);
  mass.reset();
  EXPECT_EQ(mass.force({.velocity = 0.5}), 0.0);
}

TEST(LearnedTerms, ValidationRefusesUnphysicalSignsAndNonFiniteValues) {
  LearnedTermsParams p;
  p[LearnedTerm::kAcceleration] = -1.0;
  p[LearnedTerm::kDisplacement] = -1.0;  // either sign: a spring may pull or push
  p[LearnedTerm::kVelocity] = std::nan("");
  const auto report = validate(p);
  ASSERT_EQ(report.issues().size(), 2u) << report.to_string();
  EXPECT_EQ(report.issues()[0].field, "velocity");
  EXPECT_EQ(report.issues()[1].field, "acceleration");
}

// A 50 kg mass on a 2 Hz sine: the observer's force rises by m a, a = -A w^2 sin(w t), to the
// backward difference's half-period lag.
TEST(LearnedTerms, TheObserverAddsTheTermsToTheBaseForce) {
  mrd::model::DamperModel with_mass;
  auto& p = with_mass.effects.get<LearnedTermsEffect>();
  p.enabled = true;
  p[LearnedTerm::kAcceleration] = 50.0;
  p[LearnedTerm::kSignVelocity] = 30.0;
  mrd::model::Observer base{mrd::model::DamperModel{}}, learned(with_mass);
  const double A = 0.02, w = 2.0 * std::numbers::pi * 2.0, dt = 1e-3;
  for (int k = 0; k < 2000; ++k) {
    const double t = k * dt;
    const mrd::model::Measurement m{.displacement = A * std::sin(w * t), .velocity = A * w * std::cos(w * t),
                                    .coil_current = 0.5};
    const double added = learned.step(m).force - base.step(m).force;
    if (k == 0) continue;
    const double a = -A * w * w * std::sin(w * (t - 0.5 * dt));
    const double friction = 30.0 * std::tanh(*m.velocity / mrd::model::kLearnedSignVelocity);
    ASSERT_NEAR(added, 50.0 * a + friction, 0.01 * 50.0 * A * w * w) << k;
  }
}

// A velocity rising at a constant 3 m/s^2, sampled unevenly: with each step's length the mass
// term is m a exactly; a period a sample would make it m a T / dt.
TEST(LearnedTerms, TheAccelerationTakesEachStepsOwnLength) {
  mrd::model::DamperModel with_mass;
  auto& p = with_mass.effects.get<LearnedTermsEffect>();
  p.enabled = true;
  p[LearnedTerm::kAcceleration] = 50.0;
  mrd::model::Observer base{mrd::model::DamperModel{}}, learned(with_mass);
  double t = 0.0;
  for (int k = 0; k < 200; ++k) {
    const double dt = k % 2 == 0 ? 0.7e-3 : 1.3e-3;
    t += dt;
    const mrd::model::Measurement m{.displacement = 1.5 * t * t, .velocity = 3.0 * t, .coil_current = 0.5,
                                    .step_duration = dt};
    const double added = learned.step(m).force - base.step(m).force;
    if (k > 0) ASSERT_NEAR(added, 50.0 * 3.0, 1e-6) << k;
  }
}

}  // namespace
