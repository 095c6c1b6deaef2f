// The two-storey building and its LQR design against results derived by hand.
#include "tools/force_run/shear_building.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

namespace {
namespace shear_building_test {

using mrd::tools::ShearBuilding;
constexpr double kPi = std::numbers::pi;

// Two equal storeys and floors: w^2 = (k/m) (3 -+ sqrt 5) / 2.
TEST(ShearBuilding, NaturalFrequenciesMatchTheClosedForm) {
  ShearBuilding b;
  b.floor_mass = 12e3;
  b.storey_stiffness = 5e6;
  const Eigen::Vector2d f = mrd::tools::natural_frequencies(b);
  const double w0 = std::sqrt(b.storey_stiffness / b.floor_mass);
  EXPECT_NEAR(f(0), w0 * std::sqrt((3.0 - std::sqrt(5.0)) / 2.0) / (2.0 * kPi), 1e-9);
  EXPECT_NEAR(f(1), w0 * std::sqrt((3.0 + std::sqrt(5.0)) / 2.0) / (2.0 * kPi), 1e-9);
  EXPECT_NEAR(mrd::tools::natural_frequencies(ShearBuilding{})(0), 2.0, 1e-3);  // the documented default
}

// Steady harmonic ground motion: the time integration's first-floor amplitude against the
// complex frequency response X = (K - w^2 M + i w C)^-1 (-M 1 a), solved by Cramer's rule.
TEST(ShearBuilding, HarmonicResponseMatchesTheFrequencyResponse) {
  const ShearBuilding b;
  const auto s = mrd::tools::structure_matrices(b);
  const double dt = 1e-3;
  for (const double f : {1.2, 2.0, 4.5}) {
    const double w = 2.0 * kPi * f;
    std::vector<double> ground;
    for (int i = 0; i < 60000; ++i) ground.push_back(1.0 * std::sin(w * i * dt));
    const Eigen::RowVector4d no_control = Eigen::RowVector4d::Zero();
    const auto r = mrd::tools::simulate_structure(b, no_control, ground, dt, [](double, double) { return 0.0; });
    double amplitude = 0.0;  // the last 10 s: the transient has decayed (2 % damping, 2 Hz)
    for (std::size_t i = 50000; i < r.drift.size(); ++i) amplitude = std::fmax(amplitude, std::fabs(r.drift[i]));

    using C = std::complex<double>;
    const C j(0.0, 1.0);
    const C d11 = s.stiffness(0, 0) - w * w * s.mass(0, 0) + j * w * s.damping(0, 0);
    const C d12 = s.stiffness(0, 1) + j * w * s.damping(0, 1);
    const C d21 = s.stiffness(1, 0) + j * w * s.damping(1, 0);
    const C d22 = s.stiffness(1, 1) - w * w * s.mass(1, 1) + j * w * s.damping(1, 1);
    const C p1 = -s.mass(0, 0), p2 = -s.mass(1, 1);
    const C x1 = (p1 * d22 - d12 * p2) / (d11 * d22 - d12 * d21);
    EXPECT_NEAR(amplitude, std::abs(x1), 0.01 * std::abs(x1)) << f << " Hz";
  }
}

// The first mode's damping is the one asked for: the free decay's logarithmic decrement.
TEST(ShearBuilding, FirstModeHasTheRequestedDamping) {
  ShearBuilding b;
  b.damping_ratio = 0.05;
  const Eigen::Matrix4d A = mrd::tools::state_space(b).A;
  const Eigen::EigenSolver<Eigen::Matrix4d> es(A);
  double zeta_first = 1.0, slowest = 1e9;
  for (int i = 0; i < 4; ++i) {
    const auto l = es.eigenvalues()(i);
    if (std::abs(l) < slowest) {
      slowest = std::abs(l);
      zeta_first = -l.real() / std::abs(l);
    }
  }
  EXPECT_NEAR(zeta_first, 0.05, 1e-9);
  EXPECT_NEAR(slowest / (2.0 * kPi), 2.0, 0.01);
}

// The double integrator x'' = u with Q = I, R = 1: P = [sqrt3 1; 1 sqrt3], G = [1 sqrt3].
TEST(Lqr, DoubleIntegratorMatchesTheClosedForm) {
  Eigen::MatrixXd A(2, 2), B(2, 1), Q = Eigen::MatrixXd::Identity(2, 2), R = Eigen::MatrixXd::Identity(1, 1);
  A << 0, 1, 0, 0;
  B << 0, 1;
  const Eigen::MatrixXd P = mrd::tools::solve_care(A, B, Q, R);
  EXPECT_NEAR(P(0, 0), std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(P(0, 1), 1.0, 1e-9);
  EXPECT_NEAR(P(1, 1), std::sqrt(3.0), 1e-9);
  const Eigen::MatrixXd G = mrd::tools::lqr_gain(A, B, Q, R);
  EXPECT_NEAR(G(0, 0), 1.0, 1e-9);
  EXPECT_NEAR(G(0, 1), std::sqrt(3.0), 1e-9);
}

// On the building: the Riccati residual vanishes, the closed loop is stable, and the demand
// resists the first storey's motion (a positive velocity gain in the damper's sign).
TEST(Lqr, BuildingDesignSolvesTheRiccatiEquationAndStabilises) {
  const ShearBuilding b;
  const auto ss = mrd::tools::state_space(b);
  const Eigen::RowVector4d G = mrd::tools::clipped_optimal_gain(b, {.force_weight = 1.0});
  const Eigen::Matrix4d closed = ss.A - ss.B * G;
  const Eigen::EigenSolver<Eigen::Matrix4d> es(closed);
  for (int i = 0; i < 4; ++i) EXPECT_LT(es.eigenvalues()(i).real(), 0.0);
  // More damping than the bare building's 2 % in the first mode.
  const Eigen::EigenSolver<Eigen::Matrix4d> open(ss.A);
  double open_decay = 1e9, closed_decay = 1e9;
  for (int i = 0; i < 4; ++i) {
    open_decay = std::fmin(open_decay, -open.eigenvalues()(i).real());
    closed_decay = std::fmin(closed_decay, -es.eigenvalues()(i).real());
  }
  EXPECT_GT(closed_decay, 1.5 * open_decay);
  EXPECT_LT(G(2), 0.0);  // f_c = -G z: a floor moving up is resisted, f_c has v's sign
}

TEST(KanaiTajimi, ScaledToItsPeakAndDeterministic) {
  const mrd::tools::KanaiTajimi g;
  const auto a = mrd::tools::kanai_tajimi_ground_motion(g, 20.0, 1e-3, 3);
  double peak = 0.0;
  for (const double v : a) peak = std::fmax(peak, std::fabs(v));
  EXPECT_NEAR(peak, g.peak_acceleration, 1e-9);
  EXPECT_EQ(a, mrd::tools::kanai_tajimi_ground_motion(g, 20.0, 1e-3, 3));
  EXPECT_NE(a, mrd::tools::kanai_tajimi_ground_motion(g, 20.0, 1e-3, 4));
  double first_tenth = 0.0;  // the envelope (t / 2 s)^2 is 0.0025 at 0.1 s
  for (int i = 0; i < 100; ++i) first_tenth = std::fmax(first_tenth, std::fabs(a[static_cast<std::size_t>(i)]));
  EXPECT_LT(first_tenth, 0.01 * g.peak_acceleration);
}

}  // namespace shear_building_test
}  // namespace
