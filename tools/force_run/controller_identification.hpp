#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/damper_model.hpp"
#include "model/hysteresis_compensator.hpp"

// The "identified" controller model of mrd-force-run: the plant identified on noisy simulated
// measurements with the project's own tools, never copied from it (docs/FORCE-CONTROL.md).
namespace mrd::tools {

struct ControllerIdentificationOptions {
  double bh_noise_rms = 0.01;       // on the B of the simulated B-H loop [T]
  double force_noise_rms = 200.0;   // load cell of the simulated force run [N]
  double force_run_duration = 20.0;  // [s]
  std::uint64_t seed = 1;
};

struct IdentifiedController {
  model::DamperModel model;
  double bh_rmse = 0.0;        // the J-A fit's Eq. 15 RMSE on the noisy loop [T]
  double force_fit_rms = 0.0;  // the force fit's residual RMS on the noisy run [N]
  std::vector<std::string> notes;
};

// 1. Eq. 1-10: mrd-identify's improved PSO and polish on one major B-H loop of the plant's
//    material to the field of `limits.max_current`, with white noise on B.
// 2. Eq. 11-13: mrd-residual's model fit (the base space with the field gain kept: v_s, and the
//    linear terms: force scale and viscous coefficient) on a simulated force run of the plant
//    (random motion, random held current levels slewed by the driver, load-cell noise), from the
//    catalogue guess `nominal` with the identified J-A parameters.
// 3. When the plant has a coil lag: its time constant fitted the same way on that run.
IdentifiedController identify_controller(const model::DamperModel& plant, const model::DamperModel& nominal,
                                         const model::CompensatorLimits& limits,
                                         const ControllerIdentificationOptions& options = {});

}  // namespace mrd::tools
