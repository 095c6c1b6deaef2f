#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "control/control_law.hpp"
#include "model/force_inverse.hpp"
#include "model/hysteresis_compensator.hpp"
#include "model/observer.hpp"
#include "tests/support/allocation_counter.hpp"

namespace {

using mrd::test::start_counting_allocations;
using mrd::test::stop_counting_allocations;

// The hook itself must see allocations, or the zero below proves nothing.
TEST(AllocationCounter, SeesNewVectorGrowthAndMalloc) {
  start_counting_allocations();
  auto owned = std::make_unique<double>(1.0);
  std::vector<int> v;
  for (int i = 0; i < 100; ++i) v.push_back(i);
  void* raw = std::malloc(64);
  std::string long_text(100, 'x');
  const auto count = stop_counting_allocations();
  std::free(raw);
  EXPECT_GE(count, 4u);
}

double sine_current(int i) {  // 0.5 Hz sine of 0..1.2 A at 1 kHz
  return 0.6 + 0.6 * std::sin(2.0 * std::numbers::pi * 0.5 * i * 1e-3);
}

TEST(RealTime, ObserverAndCompensatorStepsDoNotAllocate) {
  const mrd::model::DamperModel model;
  mrd::model::Observer observer(model);
  const mrd::model::TargetCurve target(observer.magnetics(), 1.5);
  mrd::model::HysteresisCompensator compensator(observer.magnetics(), target, {}, 1e-3);

  double sink = 0.0;
  start_counting_allocations();
  for (int i = 0; i < 100000; ++i) {
    const double x = 0.04 * std::sin(2.0 * std::numbers::pi * 0.5 * i * 1e-3);
    const double command = compensator.command(sine_current(i), observer.magnetics());
    sink += observer.step({.displacement = x, .coil_current = command}).force;
  }
  const auto count = stop_counting_allocations();
  EXPECT_EQ(count, 0u);
  EXPECT_TRUE(std::isfinite(sink));
}

// The force inverse with a coil lag declared (its inversion runs), on a demand that is
// dissipative, then pushes with the motion, then is not finite.
TEST(RealTime, ForceInverseStepDoesNotAllocate) {
  mrd::model::DamperModel model;
  model.effects.get<mrd::model::CoilLagEffect>() = {true, 20e-3};
  mrd::model::Observer observer(model);
  mrd::model::ForceInverse inverse(observer, {});
  double sink = 0.0;
  start_counting_allocations();
  for (int i = 0; i < 100000; ++i) {
    const double phase = 2.0 * std::numbers::pi * 0.5 * i * 1e-3;
    const double x = 0.04 * std::sin(phase);
    const double v = 0.04 * std::numbers::pi * std::cos(phase);
    const double force = i % 3 == 0 ? 250e3 * v : (i % 3 == 1 ? -250e3 * v : std::nan(""));
    const auto command = inverse.step({.force = force, .velocity = v}, observer);
    sink += observer.step({.displacement = x, .velocity = v, .coil_current = command.current}).force;
  }
  EXPECT_EQ(stop_counting_allocations(), 0u);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(RealTime, ControlLawObserveAndCommandDoNotAllocate) {
  mrd::control::ControlLaw law(mrd::control::ControlLawConfig{});
  double coil = 0.0;
  start_counting_allocations();
  for (int i = 0; i < 100000; ++i) {
    const double x = 0.045 * std::sin(2.0 * std::numbers::pi * 0.5 * i * 1e-3);
    law.observe({.displacement = x, .coil_current = coil});
    coil = law.command().current;
  }
  EXPECT_EQ(stop_counting_allocations(), 0u);
  EXPECT_TRUE(std::isfinite(coil));
}

}  // namespace
