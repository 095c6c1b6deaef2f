#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "control/control_law.hpp"
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
