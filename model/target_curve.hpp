#pragma once

#include <array>
#include <cstddef>

#include "model/jiles_atherton.hpp"

namespace mrd::model {

// The B a current is meant to give if the core had no hysteresis: what Table 4's currents
// intend. Tabulated once at start-up over [0, max_current]; odd in the current.
class TargetCurve {
 public:
  enum class Kind {
    kAnhysteretic,  // M = Man(H + alpha M): the hysteresis-free curve (Eq. 3-4)
    kInitial,       // the virgin magnetisation curve from the demagnetised state
  };
  static constexpr std::size_t kPoints = 257;

  TargetCurve(const JilesAtherton& prototype, double max_current, Kind kind = Kind::kAnhysteretic);

  [[nodiscard]] double B(double current) const;  // [T], linear interpolation
  [[nodiscard]] double max_current() const { return max_current_; }
  [[nodiscard]] Kind kind() const { return kind_; }

 private:
  std::array<double, kPoints> B_{};
  double max_current_;
  double step_;
  Kind kind_;
};

}  // namespace mrd::model
