#include "model/mr_fluid.hpp"

#include <algorithm>
#include <cmath>

namespace mrd::model {

ParameterReport validate(const MrFluid& fluid) {
  ParameterReport report;
  report.require_positive("viscosity", fluid.viscosity);
  report.require_in_range("volume_fraction", fluid.volume_fraction, 0.0, 0.74, false);
  report.require_positive("particle_diameter", fluid.particle_diameter);
  report.require_positive("particle_saturation", fluid.particle_saturation);
  if (report.ok() && fluid.particle_diameter > 1e-3) {
    report.error("particle_diameter", "must be given in metres (MR particles are 0.1-100 um)");
  }
  return report;
}

YieldStress::YieldStress(const MrFluid& fluid)
    : field_gain_(146960.0 * std::pow(fluid.volume_fraction, 1.706) *
                  std::pow(fluid.particle_diameter * 1e6, 0.2) *  // m -> um, the fit's unit
                  std::pow(fluid.particle_saturation, 0.8)),
      offset_(1083.2 * fluid.volume_fraction - 287.03) {}

double YieldStress::operator()(double B) const {
  return std::max(0.0, field_gain_ * std::pow(std::fabs(B), 0.5811) + offset_);  // Eq. 13
}

}  // namespace mrd::model
