#include "tools/force_run/shear_building.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace mrd::tools {

StructureMatrices structure_matrices(const ShearBuilding& b) {
  StructureMatrices s;
  const double m = b.floor_mass, k = b.storey_stiffness;
  s.mass << m, 0.0, 0.0, m;
  s.stiffness << 2.0 * k, -k, -k, k;
  // Stiffness-proportional damping: zeta_1 = a1 w1 / 2.
  const double w1 = 2.0 * std::numbers::pi * natural_frequencies(b)(0);
  s.damping = (2.0 * b.damping_ratio / w1) * s.stiffness;
  return s;
}

Eigen::Vector2d natural_frequencies(const ShearBuilding& b) {
  // M = m I, so K phi = w^2 M phi is the symmetric 2x2 eigenproblem of K / m: its eigenvalues
  // from the trace and the discriminant (Eigen's generalised solver cost a minute to compile).
  const double k = b.storey_stiffness / b.floor_mass;
  Eigen::Matrix2d A;
  A << 2.0 * k, -k, -k, k;
  const double mean = 0.5 * A.trace();
  const double radius = std::hypot(0.5 * (A(0, 0) - A(1, 1)), A(0, 1));
  return Eigen::Vector2d(std::sqrt(mean - radius), std::sqrt(mean + radius)) / (2.0 * std::numbers::pi);
}

StateSpace state_space(const ShearBuilding& b) {
  const StructureMatrices s = structure_matrices(b);
  const Eigen::Matrix2d Minv = s.mass.inverse();
  StateSpace ss;
  ss.A.setZero();
  ss.A.topRightCorner<2, 2>().setIdentity();
  ss.A.bottomLeftCorner<2, 2>() = -Minv * s.stiffness;
  ss.A.bottomRightCorner<2, 2>() = -Minv * s.damping;
  ss.B.setZero();
  ss.B.tail<2>() = Minv * Eigen::Vector2d(-1.0, 0.0);  // the damper pushes floor 1 back
  ss.E.setZero();
  ss.E.tail<2>() = Eigen::Vector2d(-1.0, -1.0);  // the ground's inertia load, -M 1 a_g / m
  return ss;
}

Eigen::MatrixXd solve_care(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                           const Eigen::MatrixXd& R) {
  const Eigen::Index n = A.rows();
  Eigen::MatrixXd H(2 * n, 2 * n);
  H << A, -B * R.inverse() * B.transpose(), -Q, -A.transpose();
  // sign(H) by Newton: Z <- (Z / c + c Z^-1) / 2, c = |det Z|^(1/2n).
  Eigen::MatrixXd Z = H;
  for (int i = 0; i < 100; ++i) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(Z);
    const double c = std::pow(std::fabs(lu.determinant()), 1.0 / static_cast<double>(2 * n));
    const Eigen::MatrixXd next = 0.5 * (Z / c + c * lu.inverse());
    const double change = (next - Z).norm() / next.norm();
    Z = next;
    if (change < 1e-13) break;
  }
  // The stable subspace is spanned by [I; P] and sign(H) is -I on it:
  // [W12; W22 + I] P = -[W11 + I; W21].
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd lhs(2 * n, n), rhs(2 * n, n);
  lhs << Z.topRightCorner(n, n), Z.bottomRightCorner(n, n) + I;
  rhs << Z.topLeftCorner(n, n) + I, Z.bottomLeftCorner(n, n);
  const Eigen::MatrixXd P = lhs.colPivHouseholderQr().solve(-rhs);
  return 0.5 * (P + P.transpose());
}

Eigen::MatrixXd lqr_gain(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                         const Eigen::MatrixXd& R) {
  return R.inverse() * B.transpose() * solve_care(A, B, Q, R);
}

Eigen::RowVector4d clipped_optimal_gain(const ShearBuilding& b, const LqrWeights& w) {
  const StateSpace ss = state_space(b);
  // Drifts d = T z: d1 = x1, d2 = x2 - x1; Q = (k T)'(k T).
  Eigen::Matrix<double, 2, 4> T = Eigen::Matrix<double, 2, 4>::Zero();
  T(0, 0) = 1.0;
  T(1, 0) = -1.0;
  T(1, 1) = 1.0;
  T *= b.storey_stiffness;
  const Eigen::Matrix4d Q = T.transpose() * T;
  const Eigen::MatrixXd R = Eigen::MatrixXd::Constant(1, 1, w.force_weight);
  // u = -G z is the force the damper applies; f_c = -G z in its own sign convention.
  return lqr_gain(ss.A, ss.B, Q, R);
}

std::vector<double> kanai_tajimi_ground_motion(const KanaiTajimi& g, double duration, double dt,
                                               std::uint64_t seed) {
  const auto n = static_cast<std::size_t>(std::llround(duration / dt));
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> white(0.0, 1.0 / std::sqrt(dt));  // unit spectral intensity
  const double w = 2.0 * std::numbers::pi * g.ground_frequency;
  double x = 0.0, xd = 0.0, peak = 0.0;
  std::vector<double> a(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    // Semi-implicit Euler: dt w = 0.016 at 1 kHz, well inside its stability.
    xd += dt * (white(rng) - 2.0 * g.ground_damping * w * xd - w * w * x);
    x += dt * xd;
    const double envelope = t < g.rise_end     ? (t / g.rise_end) * (t / g.rise_end)
                            : t < g.strong_end ? 1.0
                                               : std::exp(-g.decay_rate * (t - g.strong_end));
    a[i] = -envelope * (2.0 * g.ground_damping * w * xd + w * w * x);
    peak = std::fmax(peak, std::fabs(a[i]));
  }
  if (peak > 0.0) {
    for (double& v : a) v *= g.peak_acceleration / peak;
  }
  return a;
}

StructureResponse simulate_structure(const ShearBuilding& b, const Eigen::RowVector4d& gain,
                                     const std::vector<double>& ground, double dt,
                                     const std::function<double(double, double)>& applied) {
  const StateSpace ss = state_space(b);
  StructureResponse r;
  r.drift.reserve(ground.size());
  r.velocity.reserve(ground.size());
  r.desired.reserve(ground.size());
  r.applied.reserve(ground.size());
  Eigen::Vector4d z = Eigen::Vector4d::Zero();
  for (const double ag : ground) {
    const double desired = -gain.dot(z);
    const double f = applied(desired, z(2));
    r.drift.push_back(z(0));
    r.velocity.push_back(z(2));
    r.desired.push_back(desired);
    r.applied.push_back(f);
    const auto rate = [&](const Eigen::Vector4d& s) -> Eigen::Vector4d { return ss.A * s + ss.B * f + ss.E * ag; };
    const Eigen::Vector4d k1 = rate(z);
    const Eigen::Vector4d k2 = rate(z + 0.5 * dt * k1);
    const Eigen::Vector4d k3 = rate(z + 0.5 * dt * k2);
    const Eigen::Vector4d k4 = rate(z + dt * k3);
    z += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    r.peak_top_drift = std::fmax(r.peak_top_drift, std::fabs(z(1) - z(0)));
  }
  return r;
}

}  // namespace mrd::tools
