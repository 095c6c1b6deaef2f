#pragma once

namespace mrd::model {

// Vacuum permeability [H/m] (CODATA 2018), used in Eq. 8.
inline constexpr double kMu0 = 1.25663706212e-6;

}  // namespace mrd::model
