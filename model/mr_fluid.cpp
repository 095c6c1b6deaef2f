#include "model/mr_fluid.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "model/compile_time_fit.hpp"
#include "model/saturating_shape.hpp"
#include "model/typical_ranges.hpp"

namespace mrd::model {

ValidationReport validate(const MrFluid& fluid) {
  ValidationReport report;
  report.require_positive("viscosity", fluid.viscosity, 1e3);  // [Pa s]: carrier oils are 0.01-10
  report.require_in_range("volume_fraction", fluid.volume_fraction, 0.0, 0.74, false);
  report.require_positive("particle_diameter", fluid.particle_diameter);
  report.require_positive("particle_saturation", fluid.particle_saturation, 3.0);  // mu0 Ms [T]: iron 2.1
  report.require_in_range("field_exponent", fluid.field_exponent, 0.2, 1.5, false);
  const double b_s = fluid.saturation_induction;
  if (b_s != 0.0 && !(b_s >= 0.02 && b_s <= 50.0)) {
    char got[32];
    std::snprintf(got, sizeof got, "%g", b_s);
    report.error("saturation_induction", std::string("must be 0 (no saturation) or lie in [0.02, 50] T, got ") + got);
  }
  report.require_in_range("saturation_shape", fluid.saturation_shape, -1.0, 2.0, false);
  report.require_in_range("flow_index", fluid.flow_index, 0.3, 2.0, false);
  if (report.ok() && fluid.particle_diameter > 1e-3) {
    report.error("particle_diameter", "must be given in metres (MR particles are 0.1-100 um)");
  }
  if (!report.ok()) return report;
  report.expect_typical("viscosity", fluid.viscosity, kTypicalViscosity.lo, kTypicalViscosity.hi, "MR fluids [Pa s]");
  report.expect_typical("field_exponent", fluid.field_exponent, kTypicalFieldExponent.lo, kTypicalFieldExponent.hi,
                        "MR fluids' yield power laws");
  report.expect_typical("flow_index", fluid.flow_index, kTypicalFlowIndex.lo, kTypicalFlowIndex.hi, "MR fluids");
  return report;
}

YieldStress::YieldStress(const MrFluid& fluid)
    : field_gain_(146960.0 * std::pow(fluid.volume_fraction, 1.706) *
                  std::pow(fluid.particle_diameter * 1e6, 0.2) *  // m -> um, the fit's unit
                  std::pow(fluid.particle_saturation, 0.8)),
      offset_(1083.2 * fluid.volume_fraction - 287.03),
      exponent_(fluid.field_exponent),
      paper_exponent_(fluid.field_exponent == kEq13FieldExponent),
      saturation_(fluid.saturation_induction),
      saturated_power_(saturation_ > 0.0 ? std::pow(saturation_, exponent_) : 0.0),
      saturation_shape_(fluid.saturation_shape) {}

namespace {

constexpr double kEq13Exponent = kEq13FieldExponent;
constexpr int kPowerCoefficients = 8;  // degree 7
constexpr int kMinBinaryExponent = -32;
constexpr int kMaxBinaryExponent = 31;

struct PowerTable {
  // m^p on [1 + j/16, 1 + (j + 1)/16], as monomials in t = m - (1 + (2j + 1)/32).
  struct alignas(64) Interval {
    std::array<double, kPowerCoefficients> coefficients;
  };
  std::array<Interval, 16> mantissa;
  std::array<double, kMaxBinaryExponent - kMinBinaryExponent + 1> scale;  // 2^(p e)
};

constexpr PowerTable make_power_table() {
  using compile_time::Real;
  constexpr Real p = kEq13Exponent;  // the double std::pow would get, exactly
  PowerTable table{};
  for (std::size_t j = 0; j < table.mantissa.size(); ++j) {
    table.mantissa[j].coefficients = compile_time::chebyshev_fit<kPowerCoefficients>(
        [](Real m) { return compile_time::exp(p * compile_time::log(m)); },
        1.0L + (2.0L * static_cast<Real>(j) + 1.0L) / 32.0L, 1.0L / 32.0L);
  }
  for (int e = kMinBinaryExponent; e <= kMaxBinaryExponent; ++e) {
    table.scale[static_cast<std::size_t>(e - kMinBinaryExponent)] =
        static_cast<double>(compile_time::exp(p * e * compile_time::kLn2));
  }
  return table;
}

constinit const PowerTable kPowerTable = make_power_table();

}  // namespace

double eq13_field_power(double abs_B) {
  if (!(abs_B >= 0x1p-32 && abs_B < 0x1p32)) return std::pow(abs_B, kEq13Exponent);
  // A positive normal double is 2^e m: the exponent field holds e + 1023, the mantissa field
  // m - 1, and its top 4 bits pick the interval j. Setting the exponent field to that of 1
  // gives m; keeping only the top 4 bits and adding 2^-5 gives the interval's centre.
  constexpr std::uint64_t kOne = 0x3ff0000000000000;
  constexpr std::uint64_t kMantissa = 0x000fffffffffffff;
  constexpr std::uint64_t kTop4 = 0x000f000000000000;
  constexpr std::uint64_t kHalfInterval = 0x0000800000000000;  // 2^-5 in [1, 2)
  const auto bits = std::bit_cast<std::uint64_t>(abs_B);
  const double m = std::bit_cast<double>((bits & kMantissa) | kOne);
  const double centre = std::bit_cast<double>((bits & kTop4) | kOne | kHalfInterval);
  const double t = m - centre;  // exact, |t| <= 1/32
  const auto& c = kPowerTable.mantissa[(bits & kTop4) >> 48].coefficients;
  const double t2 = t * t;
  const double t4 = t2 * t2;
  const double m_power = ((c[0] + c[1] * t) + (c[2] + c[3] * t) * t2) +
                         ((c[4] + c[5] * t) + (c[6] + c[7] * t) * t2) * t4;
  const auto e = static_cast<int>(bits >> 52) - 1023;
  return m_power * kPowerTable.scale[static_cast<std::size_t>(e - kMinBinaryExponent)];
}

double YieldStress::operator()(double B) const {
  const double abs_B = std::fabs(B);
  const double power = paper_exponent_ ? eq13_field_power(abs_B) : std::pow(abs_B, exponent_);
  if (saturation_ > 0.0) {
    // (B / B_s)^n = B^n / B_s^n
    const double bent = saturated_power_ * saturating_shape(power / saturated_power_, saturation_shape_);
    return std::max(0.0, field_gain_ * bent + offset_);
  }
  return std::max(0.0, field_gain_ * power + offset_);  // Eq. 13
}

double YieldStress::induction(double tau) const {
  const double field_part = tau - offset_;  // Eq. 13: the B^0.5811 term alone
  if (!(field_part > 0.0) || !(tau > 0.0)) return 0.0;  // also NaN
  if (saturation_ > 0.0) {
    // Past the ceiling no B gives more: the least B within 1e-12 of it.
    const double share = std::min(field_part / (field_gain_ * saturated_power_), 1.0 - 1e-12);
    return saturation_ * std::pow(saturating_shape_inverse(share, saturation_shape_), 1.0 / exponent_);
  }
  return std::pow(field_part / field_gain_, 1.0 / exponent_);
}

}  // namespace mrd::model
