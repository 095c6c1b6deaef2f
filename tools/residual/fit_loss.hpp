#pragma once

#include <cmath>
#include <cstdint>

namespace mrd::tools {

// What a fit minimises over its samples' residuals r [N] (docs/CLOSING-THE-LOOP.md, "Robust
// fit"). The knee c [N] is the fit's, fixed: a trial's own scale would let a model that errs
// widely but with a narrow core pay less for a fault's samples.
struct FitLoss {
  enum class Kind : std::uint8_t {
    kSquares,  // r^2
    kHuber,    // r^2 inside the knee, 2c|r| - c^2 beyond: a fault pulls with c per sample
    kCauchy,   // c^2 log(1 + (r/c)^2): a fault far beyond the knee pulls with c^2/r, fading
  };
  Kind kind = Kind::kSquares;
  double knee = 0.0;  // [N], > 0 unless kSquares

  [[nodiscard]] bool squares() const { return kind == Kind::kSquares || !(knee > 0.0); }
  // rho(r): r^2 well inside the knee, so that sqrt(mean rho) reads as an RMS [N].
  [[nodiscard]] double rho(double r) const {
    if (squares()) return r * r;
    const double a = std::fabs(r);
    if (kind == Kind::kHuber) return a <= knee ? r * r : 2.0 * knee * a - knee * knee;
    return knee * knee * std::log1p((r / knee) * (r / knee));
  }
  // The reweighted least squares' weight of r: rho'(r) / 2r.
  [[nodiscard]] double weight(double r) const {
    if (squares()) return 1.0;
    const double a = std::fabs(r);
    if (kind == Kind::kHuber) return a <= knee ? 1.0 : knee / a;
    return 1.0 / (1.0 + (r / knee) * (r / knee));
  }
};

}  // namespace mrd::tools
