// The simulated rig's motion profiles (sim/displacement_profile.hpp) against their analytic
// values at known times, and each velocity against a central difference of its displacement.
#include "sim/displacement_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>

namespace {
namespace motion_profiles {  // its own names in the unity build

using mrd::sim::DisplacementProfile;
using mrd::sim::PlaybackProfile;
using mrd::sim::RandomProfile;
using mrd::sim::SineProfile;
using mrd::sim::SineSequenceProfile;

// A time [s] and the displacement [m] and velocity [m/s] a profile has then.
struct Known {
  double t, x, v;
};

template <typename Profile>
void expect_motion(const Profile& profile, std::initializer_list<Known> known) {
  for (const Known& k : known) {
    EXPECT_NEAR(profile.displacement(k.t), k.x, 1e-15) << "t " << k.t;
    EXPECT_NEAR(profile.velocity(k.t), k.v, 1e-15) << "t " << k.t;
  }
}

// The velocity a profile reports against the slope of its displacement, (x(t+h) - x(t-h)) / 2h,
// at `times`; the difference's error is h^2 x'''(t) / 6.
template <typename Profile>
void expect_velocity_is_the_slope(const Profile& profile, std::initializer_list<double> times, double tolerance) {
  const double h = 1e-6;
  for (const double t : times) {
    EXPECT_NEAR(profile.velocity(t), (profile.displacement(t + h) - profile.displacement(t - h)) / (2.0 * h),
                tolerance)
        << "t " << t;
  }
}

TEST(SineProfile, ThePapersSineAtQuarterAndEighthPeriods) {
  const SineProfile sine;  // 40 mm, 0.5 Hz: omega = pi rad/s, peak speed 0.04 pi m/s
  const double peak_speed = 0.12566370614359174;
  const double root_half = 0.70710678118654752;
  expect_motion(sine, {{0.0, 0.0, peak_speed},
                       {0.25, 0.04 * root_half, peak_speed * root_half},
                       {0.5, 0.04, 0.0},
                       {1.0, 0.0, -peak_speed},
                       {1.5, -0.04, 0.0},
                       {2.0, 0.0, peak_speed},
                       {6.25, 0.04 * root_half, peak_speed * root_half}});  // 3 periods on
}

TEST(SineProfile, AnotherAmplitudeAndFrequency) {
  const SineProfile sine{.amplitude = 0.005, .frequency = 4.0};  // omega = 8 pi rad/s
  const double peak_speed = 0.005 * 8.0 * 3.14159265358979324;
  expect_motion(sine, {{0.0, 0.0, peak_speed}, {1.0 / 16.0, 0.005, 0.0}, {0.125, 0.0, -peak_speed}});
  expect_velocity_is_the_slope(sine, {0.01, 0.07, 0.2, 0.33}, 1e-7);
}

TEST(SineSequenceProfile, WholeCyclesOfEachFrequencyInTurn) {
  const SineSequenceProfile sines(0.01, {1.0, 2.0, 0.5}, 2);
  EXPECT_DOUBLE_EQ(sines.duration(), 2.0 + 1.0 + 4.0);
  // Each segment starts at x = 0 moving up at its own peak speed, A 2 pi f.
  const double two_pi_a = 2.0 * 3.14159265358979324 * 0.01;
  expect_motion(sines, {{0.0, 0.0, two_pi_a * 1.0}, {0.25, 0.01, 0.0}, {1.75, -0.01, 0.0},
                        {2.0, 0.0, two_pi_a * 2.0}, {2.125, 0.01, 0.0}, {2.375, -0.01, 0.0},
                        {3.0, 0.0, two_pi_a * 0.5}, {3.5, 0.01, 0.0}, {6.5, -0.01, 0.0}});
  // Across a join the motion is continuous and keeps its direction; its speed steps with f.
  for (const double join : {2.0, 3.0}) {
    EXPECT_NEAR(sines.displacement(join - 1e-9), sines.displacement(join + 1e-9), 1e-9) << join;
    EXPECT_GT(sines.velocity(join - 1e-9), 0.0) << join;
  }
}

TEST(RandomProfile, ReachesItsPeakOnTheSampleGridAndNowhereBeyond) {
  const double peak = 0.03;
  const double period = 1e-3;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {  // the largest |x| falls anywhere in the run
    const RandomProfile random(peak, 0.1, 5.0, 4.0, period, seed);
    double largest = 0.0;
    for (int k = 0; k <= 4000; ++k) largest = std::fmax(largest, std::fabs(random.displacement(k * period)));
    EXPECT_NEAR(largest, peak, 1e-15) << "seed " << seed;
  }
  expect_velocity_is_the_slope(RandomProfile(peak, 0.1, 5.0, 4.0, period, 11), {0.1, 0.77, 1.5, 3.2}, 1e-7);
}

TEST(RandomProfile, TheSameSeedIsTheSameMotion) {
  const RandomProfile a(0.02, 0.5, 3.0, 2.0, 1e-3, 5);
  const RandomProfile b(0.02, 0.5, 3.0, 2.0, 1e-3, 5);
  const RandomProfile other(0.02, 0.5, 3.0, 2.0, 1e-3, 6);
  double apart = 0.0;
  for (const double t : {0.1, 0.6, 1.3, 1.9}) {
    EXPECT_EQ(a.displacement(t), b.displacement(t));
    EXPECT_EQ(a.velocity(t), b.velocity(t));
    apart = std::fmax(apart, std::fabs(a.displacement(t) - other.displacement(t)));
  }
  EXPECT_GT(apart, 1e-4);
}

TEST(PlaybackProfile, InterpolatesFromTheFirstSampleAndHoldsTheLast) {
  // Recorded at t = 10, 11, 13 s: 0, 10, -10 mm.
  const PlaybackProfile playback({10.0, 11.0, 13.0}, {0.0, 0.010, -0.010});
  EXPECT_DOUBLE_EQ(playback.duration(), 3.0);
  expect_motion(playback, {{-1.0, 0.0, 0.0}, {0.0, 0.0, 0.010}, {0.5, 0.005, 0.010}, {1.0, 0.010, -0.010},
                           {1.5, 0.005, -0.010}, {2.0, 0.0, -0.010}, {3.0, -0.010, 0.0}, {5.0, -0.010, 0.0}});
}

// The one profile type the rig and the run generator hold: it moves as the profile it holds and
// ends where that one ends, never for an endless sine or random motion.
TEST(DisplacementProfile, MovesAsTheProfileItHoldsAndEndsWhereItEnds) {
  const DisplacementProfile sine = SineProfile{.amplitude = 0.005, .frequency = 4.0};
  const double peak_speed = 0.005 * 8.0 * 3.14159265358979324;
  expect_motion(sine, {{0.0, 0.0, peak_speed}, {1.0 / 16.0, 0.005, 0.0}});
  EXPECT_EQ(sine.duration(), 0.0);
  EXPECT_EQ(DisplacementProfile(RandomProfile(0.02, 0.5, 3.0, 2.0, 1e-3, 5)).duration(), 0.0);
  EXPECT_DOUBLE_EQ(DisplacementProfile(SineSequenceProfile(0.01, {1.0, 2.0, 0.5}, 2)).duration(), 7.0);
  const DisplacementProfile playback = PlaybackProfile({10.0, 11.0, 13.0}, {0.0, 0.010, -0.010});
  EXPECT_DOUBLE_EQ(playback.duration(), 3.0);
  expect_motion(playback, {{0.5, 0.005, 0.010}, {1.5, 0.005, -0.010}});
}

}  // namespace motion_profiles
}  // namespace
