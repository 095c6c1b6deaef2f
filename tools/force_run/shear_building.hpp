#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <functional>
#include <vector>

// The outer loop of issue 18's second demand: a two-storey shear building with the damper
// between the ground and the first floor, a clipped-optimal LQR design on it (after Dyke et
// al. 1996) and a Kanai-Tajimi ground motion. Host tool code: allocates freely.
namespace mrd::tools {

// Two equal floors on equal storeys. The defaults: 30 t a floor, storey stiffness for a first
// mode at 2 Hz, 2 % damping in the first mode (stiffness proportional).
struct ShearBuilding {
  double floor_mass = 3.0e4;          // m [kg], each floor
  double storey_stiffness = 1.2405e7;  // k [N/m], each storey
  double damping_ratio = 0.02;         // first mode [-]
};

struct StructureMatrices {
  Eigen::Matrix2d mass, damping, stiffness;
};
StructureMatrices structure_matrices(const ShearBuilding& b);

// The undamped natural frequencies [Hz], lower first, from the generalised eigenproblem
// K phi = w^2 M phi.
Eigen::Vector2d natural_frequencies(const ShearBuilding& b);

// z = (x1, x2, x1', x2'), floor displacements relative to the ground [m, m/s];
//   z' = A z + B f + E a_g,
// f the damper force between ground and floor 1, positive when it resists x1' > 0 (the
// damper's own sign convention, docs/FORCE-CONTROL.md), a_g the ground acceleration [m/s^2].
struct StateSpace {
  Eigen::Matrix4d A;
  Eigen::Vector4d B;
  Eigen::Vector4d E;
};
StateSpace state_space(const ShearBuilding& b);

// The stabilising solution P of A'P + PA - P B R^-1 B'P + Q = 0 (Q symmetric >= 0, R > 0), from
// the matrix sign function of the Hamiltonian (Newton iteration with determinant scaling).
Eigen::MatrixXd solve_care(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                           const Eigen::MatrixXd& R);
// G = R^-1 B' P: the LQR law u = -G z.
Eigen::MatrixXd lqr_gain(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& Q,
                         const Eigen::MatrixXd& R);

// The design's weights: J = integral of sum_i (k d_i)^2 + r f^2, d_i the storey drifts,
// k d_i the storey shear their stiffness carries. r = 1 weighs the damper force like a storey
// shear; larger r asks for less force.
struct LqrWeights {
  double force_weight = 10.0;  // r [-]
};
// The desired damper force is f_c = -G z with G from these weights (the full state is taken as
// measured: Dyke et al. used an observer on accelerometers; that is not the subject here).
Eigen::RowVector4d clipped_optimal_gain(const ShearBuilding& b, const LqrWeights& w);

// Kanai-Tajimi filtered white noise, a_g = -(2 z w x' + w^2 x) with x'' + 2 z w x' + w^2 x = n,
// shaped by an envelope (t/t1)^2, 1 to t2, exp(-c (t - t2)) and scaled to `peak_acceleration`.
struct KanaiTajimi {
  double ground_frequency = 2.5;  // [Hz], firm soil
  double ground_damping = 0.6;    // [-]
  double peak_acceleration = 0.3 * 9.81;  // [m/s^2]
  double rise_end = 2.0;     // t1 [s]
  double strong_end = 8.0;   // t2 [s]
  double decay_rate = 0.3;   // c [1/s]
};
std::vector<double> kanai_tajimi_ground_motion(const KanaiTajimi& ground, double duration, double sample_period,
                                               std::uint64_t seed);

struct StructureResponse {
  std::vector<double> drift;     // x1, the damper's displacement [m]
  std::vector<double> velocity;  // x1' [m/s]
  std::vector<double> desired;   // f_c = -G z [N]
  std::vector<double> applied;   // the force the structure felt [N]
  double peak_top_drift = 0.0;   // max |x2 - x1| [m]
};

// The structure under `ground` (one value a period), fourth-order Runge-Kutta with the force and
// the ground acceleration held over each period; each period the force it feels is
// `applied(f_c, x1')` (the damper the motion is made with).
StructureResponse simulate_structure(const ShearBuilding& b, const Eigen::RowVector4d& gain,
                                     const std::vector<double>& ground, double sample_period,
                                     const std::function<double(double desired, double velocity)>& applied);

}  // namespace mrd::tools
