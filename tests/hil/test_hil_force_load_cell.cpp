// Force mode's load-cell feedback as two processes over Modbus TCP: mrd-plant is the rig and the
// outer controller (the demand c v), and measures its force with the load cell the controller
// reads (docs/FORCE-CONTROL.md, Load-cell feedback). The plant's fluid has a yield stress 0.8 of
// the controller's model (its thermal_drift held at 70 degC against a 20 degC reference, linear
// law, 0.004 /K, viscosity unchanged), so the correction's scale must move from 1 toward 0.8.
// 50 Hz, as the other HIL tests (docs/HIL.md).
#include <gtest/gtest.h>

#include <string>

#include "tests/hil/hil_checks.hpp"
#include "tests/hil/hil_run.hpp"

namespace {
namespace hil_force_load_cell {  // its own names in the unity build

using mrd::control::SupervisorState;
using namespace mrd::test;

constexpr double kRate = 50.0;  // [Hz]

std::string controller_toml() {
  return "[loop]\nrate = 50.0\n"
         "[backends]\nlvdt = \"modbus\"\ndriver = \"modbus\"\nlines = \"mock\"\ndemand = \"modbus\"\n"
         "load_cell = \"modbus\"\n"
         "[control]\nmode = \"force\"\n"
         "[compensator]\nmin_current = -1.5\n"
         "[force.load_cell]\ntime_constant = 0.5\n"
         "[modbus]\ntransport = \"tcp\"\npoll_period = 0.01\nresponse_timeout = 0.1\n"
         "[safety]\noverrun_limit = 1000000\nrecovery_periods = 50\n";
}

std::string plant_toml() {
  return "demand_damping = 250e3\nforce_noise = 50.0\n"
         "[profile]\nkind = \"sine\"\namplitude = 0.040\nfrequency = 0.5\n"
         "[damper.effects.thermal_drift]\nenabled = true\ninitial_temperature = 70.0\n"
         "ambient_temperature = 70.0\nreference_temperature = 20.0\nyield_law = \"linear\"\n"
         "yield_coefficient = 0.004\nviscosity_coefficient = 0.0\n";
}

TEST(HilForceLoadCell, TheScaleMovesTowardTheDriftedPlantsYieldRatio) {
  const HilResult r = run_hil({"force_load_cell", controller_toml(), plant_toml(), 6.0, true, {}});
  SCOPED_TRACE(diagnosis(r));
  expect_clean_run(r, 6.0, kRate);
  double last_scale = 1.0;
  std::size_t in_run = 0;
  for (const auto& row : r.telemetry) {
    ASSERT_GE(row.force_scale, 0.7);
    ASSERT_LE(row.force_scale, 1.3);
    if (row.state == SupervisorState::kRun) {
      last_scale = row.force_scale;
      ++in_run;
    }
  }
  ASSERT_GT(in_run, 200u) << r.controller_output;
  EXPECT_EQ(r.telemetry.front().force_scale, 1.0);
  // About 4.5 s in RUN, gated in for about two thirds of it: nine time constants.
  EXPECT_NEAR(last_scale, 0.8, 0.04) << r.controller_output;
  EXPECT_LT(r.telemetry.back().load_cell_frozen, 10u) << "the load cell is read every poll";
}

}  // namespace hil_force_load_cell
}  // namespace
