#pragma once

namespace mrd::sim {

// The paper's rig motion: x = A sin(2 pi f t), the LVDT reading in metres.
struct SineProfile {
  double amplitude = 0.040;  // [m]
  double frequency = 0.5;    // [Hz]

  [[nodiscard]] double displacement(double t) const;
  [[nodiscard]] double velocity(double t) const;
};

}  // namespace mrd::sim
