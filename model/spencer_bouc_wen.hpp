#pragma once

#include <utility>

#include "common/validation_report.hpp"

namespace mrd::model {

// Spencer, Dyke, Sain and Carlson (1997), "Phenomenological model for magnetorheological
// dampers", J. Eng. Mech. 123(3): the modified Bouc-Wen model, the field's usual reference:
//   F  = c1 y' + k1 (x - x0)
//   y' = (alpha z + c0 x' + k0 (x - y)) / (c0 + c1)
//   z' = -gamma |x' - y'| z |z|^(n-1) - beta (x' - y') |z|^n + A (x' - y')
//   alpha = alpha_a + alpha_b u,  c1 = c1a + c1b u,  c0 = c0a + c0b u
//   u' = -eta (u - v),  v the command voltage to the current driver.
// Kept here as a reference to measure our J-A + Bingham model against, not as the observer.
// SI units: N, m, s, V.
struct SpencerBoucWenParams {
  double c0a = 0.0;      // [N s/m]
  double c0b = 0.0;      // [N s/(m V)]
  double k0 = 0.0;       // [N/m]
  double c1a = 0.0;      // [N s/m]
  double c1b = 0.0;      // [N s/(m V)]
  double k1 = 0.0;       // accumulator stiffness [N/m]
  double x0 = 0.0;       // initial displacement of k1 [m]
  double alpha_a = 0.0;  // [N/m]
  double alpha_b = 0.0;  // [N/(m V)]
  double gamma = 0.0;    // [m^-n]
  double beta = 0.0;     // [m^-n]
  double A = 0.0;        // [-]
  double n = 2.0;        // [-]
  double eta = 0.0;      // [1/s]

  // The published values for Dyke's prototype damper (Lord, 1994-96), given in cm in the
  // paper and in shared/data/README.md, converted to SI: c0a 21 N s/cm = 2100 N s/m,
  // c0b 3.5 N s/(cm V) = 350 N s/(m V), k0 46.9 N/cm = 4690 N/m, c1a 283 N s/cm = 28300 N s/m,
  // c1b 2.95 N s/(cm V) = 295 N s/(m V), k1 5 N/cm = 500 N/m, x0 14.3 cm = 0.143 m,
  // alpha_a 140 N/cm = 14000 N/m, alpha_b 695 N/(cm V) = 69500 N/(m V),
  // gamma = beta = 363 cm^-2 = 3.63e6 m^-2, A = 301, n = 2, eta = 190 1/s.
  static SpencerBoucWenParams dyke_prototype();
};

ValidationReport validate(const SpencerBoucWenParams& params);

struct SpencerBoucWenState {
  double y = 0.0;  // internal displacement [m]
  double z = 0.0;  // evolutionary variable [m]
  double u = 0.0;  // filtered voltage [V]
};

// One sample of the rig as Spencer's model reads it: the command voltage, not a coil current.
struct SpencerBoucWenInput {
  double displacement = 0.0;     // x [m]
  double velocity = 0.0;         // x' [m/s]
  double command_voltage = 0.0;  // v [V]
};

// One sample per call. Within a period x and x' are linear between the last sample and this
// one and the voltage is held (the driver's command is a zero-order hold). The state (y, z, u)
// is integrated with classical RK4 over sub-steps short enough for the stiff z equation: its
// rate is about n A |x' - y'| / z_max + A alpha / (c0 + c1) + eta (with Dyke's values z_max is
// 6.4 mm and A = 301, so z crosses its range within about 20 um of travel), and each sub-step
// keeps that rate times its length below 0.5, up to max_substeps. No heap, no exceptions.
class SpencerBoucWen {
 public:
  SpencerBoucWen(const SpencerBoucWenParams& params, double sample_period, int max_substeps = 512);

  // Returns the force [N] at this sample.
  double step(const SpencerBoucWenInput& sample);
  [[nodiscard]] const SpencerBoucWenState& state() const { return state_; }
  // Starts at rest at `displacement`: y = x (k0 relaxed), z = 0, u = 0.
  void reset(double displacement = 0.0);

 private:
  struct Rates {
    double y;
    double z;
    double u;
  };
  [[nodiscard]] Rates rates(const SpencerBoucWenState& s, double x, double xdot, double voltage) const;
  // y' and c1 at the state (alpha, c0 and c1 follow the filtered voltage u).
  [[nodiscard]] std::pair<double, double> ydot_c1(const SpencerBoucWenState& s, double x, double xdot) const;

  SpencerBoucWenParams p_;
  double period_;
  int max_substeps_;
  double z_max_;
  SpencerBoucWenState state_;
  double last_x_ = 0.0;
  double last_xdot_ = 0.0;
  bool primed_ = false;
};

}  // namespace mrd::model
