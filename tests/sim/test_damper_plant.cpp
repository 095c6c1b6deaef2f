// sim::DamperPlant's step against Eq. 11-13 worked by hand for the default geometry, and its
// sensors (noise, the LVDT's delay, the coil's lag) against their analytic responses.
#include "sim/damper_plant.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/default_damper_figures.hpp"

namespace {
namespace damper_plant {  // its own names in the unity build

using mrd::model::DamperModel;
using mrd::sim::DamperPlant;
using mrd::sim::PlantReading;
using mrd::sim::PlantSettings;

constexpr double kT = 1e-3;  // [s]
constexpr double kC0 = mrd::test::kDefaultViscousCoefficient;
constexpr double kZeroFieldYieldForce = mrd::test::kDefaultZeroFieldYieldForce;
constexpr double kTanhOne = 0.76159415595576489;  // the sign term at v = v_s

// A fluid whose Eq. 13 has no zero-field stress (1083.2 V - 287.03 < 0 below V = 0.265) and a
// seal: at no field the force is the seal's and the viscous part alone.
DamperModel sealed_thin_fluid(double seal) {
  DamperModel m;
  m.fluid.volume_fraction = 0.2;
  m.geometry.seal_friction = seal;
  return m;
}

PlantReading one_step(const DamperModel& model, double v, double current) {
  DamperPlant plant(model, PlantSettings{});
  return plant.step({.displacement = 0.01, .velocity = v, .coil_current = current});
}

TEST(DamperPlant, AtNoFieldTheForceIsTheSealAndTheViscousPart) {
  const DamperModel model = sealed_thin_fluid(300.0);
  const struct {
    double v, force;
  } known[] = {{0.1, 300.0 + kC0 * 0.1},              // sign term 1 (tanh 100)
               {-0.1, -(300.0 + kC0 * 0.1)},
               {1e-3, 300.0 * kTanhOne + kC0 * 1e-3},  // v = v_s
               {0.0, 0.0}};
  for (const auto& k : known) {
    const PlantReading r = one_step(model, k.v, 0.0);
    EXPECT_EQ(r.B, 0.0) << "a virgin core at 0 A";
    EXPECT_NEAR(r.force, k.force, 1e-3) << "v " << k.v;
  }
}

TEST(DamperPlant, TheDefaultFluidAddsItsZeroFieldYieldForce) {
  const PlantReading r = one_step(DamperModel{}, 0.1, 0.0);
  EXPECT_NEAR(r.force, kZeroFieldYieldForce + kC0 * 0.1, 1e-3);
}

TEST(DamperPlant, TheForceResistsTheMotionAndIsOddInTheVelocity) {
  for (const double current : {0.0, 0.4, 1.2}) {
    for (const double v : {1e-4, 2e-3, 0.05, 0.3}) {
      // The same current history, so the same B: only the velocity's sign differs.
      const PlantReading up = one_step(DamperModel{}, v, current);
      const PlantReading down = one_step(DamperModel{}, -v, current);
      EXPECT_GT(up.force, 0.0) << current << " A, " << v << " m/s";
      EXPECT_EQ(down.force, -up.force) << current << " A, " << v << " m/s";
    }
  }
  // More current, more force at the same motion.
  EXPECT_GT(one_step(DamperModel{}, 0.1, 1.2).force, one_step(DamperModel{}, 0.1, 0.4).force + 10e3);
}

TEST(DamperPlant, WithoutNoiseOrEffectsTheSensorsReadTheTruth) {
  DamperPlant plant(DamperModel{}, PlantSettings{});
  const PlantReading r = plant.step({.displacement = 0.012, .velocity = -0.07, .coil_current = 0.8});
  EXPECT_EQ(r.true_displacement, 0.012);
  EXPECT_EQ(r.lvdt_displacement, 0.012);
  EXPECT_EQ(r.sensor_velocity, -0.07);
  EXPECT_EQ(r.coil_current, 0.8);
  EXPECT_EQ(r.measured_force, r.force);
  EXPECT_EQ(r.B, plant.physics().estimate().B);
}

TEST(DamperPlant, NoiseHasItsRmsAndTheLoadCellsOwnStream) {
  const int n = 20000;
  DamperPlant quiet_cell(DamperModel{}, PlantSettings{.lvdt_noise_rms = 5e-6, .force_noise_rms = 0.0, .seed = 4});
  DamperPlant noisy_cell(DamperModel{}, PlantSettings{.lvdt_noise_rms = 5e-6, .force_noise_rms = 50.0, .seed = 4});
  double lvdt_sum = 0.0;
  double force_sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const mrd::sim::PlantInput in{.displacement = 0.02, .velocity = 0.1, .coil_current = 0.5};
    const PlantReading a = quiet_cell.step(in);
    const PlantReading b = noisy_cell.step(in);
    // The load cell's noise does not move the LVDT's: a run with it is the same run.
    ASSERT_EQ(a.lvdt_displacement, b.lvdt_displacement) << k;
    lvdt_sum += (b.lvdt_displacement - 0.02) * (b.lvdt_displacement - 0.02);
    force_sum += (b.measured_force - b.force) * (b.measured_force - b.force);
  }
  // The RMS of 20,000 normal draws is within 3 % of sigma (its relative spread is 0.5 %).
  EXPECT_NEAR(std::sqrt(lvdt_sum / n), 5e-6, 0.03 * 5e-6);
  EXPECT_NEAR(std::sqrt(force_sum / n), 50.0, 0.03 * 50.0);
}

TEST(DamperPlant, TheLvdtReadsTheMotionItsDelayAgoAndThePhysicsDoesNot) {
  DamperModel delayed;
  delayed.effects.get<mrd::model::SensorDelayEffect>() = {.enabled = true, .delay = 2.5 * kT};
  DamperPlant plant(delayed, PlantSettings{});
  DamperPlant undelayed(DamperModel{}, PlantSettings{});
  // A ramp of 1 mm and 1 mm/s per period from 1 mm: before it the rig stood at its first value.
  for (int k = 0; k < 10; ++k) {
    const double x = 1e-3 * (k + 1);
    const double v = 1e-3 * (k + 1);
    const PlantReading r = plant.step({.displacement = x, .velocity = v, .coil_current = 0.6});
    const double late = 1e-3 * std::fmax(k + 1 - 2.5, 1.0);  // 2.5 periods ago, linearly
    EXPECT_NEAR(r.lvdt_displacement, late, 1e-15) << k;
    EXPECT_NEAR(r.sensor_velocity, late, 1e-15) << k;
    EXPECT_EQ(r.true_displacement, x);
    EXPECT_EQ(r.force, undelayed.step({.displacement = x, .velocity = v, .coil_current = 0.6}).force) << k;
  }
}

TEST(DamperPlant, TheCoilCurrentLagsTheCommandByItsTimeConstant) {
  DamperModel lagged;
  lagged.effects.get<mrd::model::CoilLagEffect>() = {.enabled = true, .time_constant = 5 * kT};
  DamperPlant plant(lagged, PlantSettings{});
  // A 1 A step held from rest: 1 - exp(-t / tau) at the end of each period.
  const double expected[] = {0.18126924692201818, 0.32967995396436067, 0.45118836390597356,
                             0.55067103588277844, 0.63212055882855767};
  for (const double i : expected) {
    EXPECT_NEAR(plant.step({.displacement = 0.0, .velocity = 0.0, .coil_current = 1.0}).coil_current, i, 1e-14);
  }
}

}  // namespace damper_plant
}  // namespace
