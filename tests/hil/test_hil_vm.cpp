// Hardware-in-the-loop over the kernel's own interfaces, inside the HIL VM (scripts/hil-vm.sh):
// mrd-controller and mrd-plant over vcan0 with the DBC's frames, the libgpiod back end on a
// gpio-sim chip, and the CAN faults. At 50 Hz: the VM emulates its CPU (TCG).
#include <gtest/gtest.h>
#include <net/if.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "firmware/config_loader.hpp"
#include "model/current_schedule.hpp"
#include "tests/hil/hil_checks.hpp"

namespace {

using namespace mrd::test;
constexpr double kRate = 50.0;

// The gpio-sim chip's line folder (sim_gpioN), made by the VM's init; "" when there is none.
std::string sim_line(int offset) {
  std::error_code ec;
  for (const auto& dev : std::filesystem::directory_iterator("/sys/devices/platform", ec)) {
    if (!dev.path().filename().string().starts_with("gpio-sim")) continue;
    for (const auto& chip : std::filesystem::directory_iterator(dev.path(), ec)) {
      if (chip.path().filename().string().starts_with("gpiochip")) {
        return (chip.path() / ("sim_gpio" + std::to_string(offset))).string();
      }
    }
  }
  return "";
}

int read_value(const std::string& line) {
  int v = -1;
  std::ifstream(line + "/value") >> v;
  return v;
}

std::string controller_toml() {
  return "[loop]\nrate = 50.0\n[backends]\nlvdt = \"can\"\ndriver = \"can\"\nlines = \"gpio\"\n"
         "[can]\ninterface = \"vcan0\"\n[gpio]\nchip = \"gpiochip0\"\n"
         "[safety]\noverrun_limit = 1000000\nrecovery_periods = 25\n";
}

const mrd::firmware::SupervisorConfig& safety() {
  static const auto config = mrd::firmware::load_config_text(controller_toml(), "vm").config.safety;
  return config;
}

HilResult run(const std::string& name, const std::string& faults, double duration,
              std::function<std::string(ChildProcess&)> watch = {}) {
  HilScenario s{name, controller_toml(),
                "rate = 50.0\n[modbus]\nenabled = false\n[can]\nenabled = true\nfault_pull = \"" +
                    sim_line(1) + "/pull\"\n[profile]\nkind = \"sine\"\namplitude = 0.040\nfrequency = 0.5\n" +
                    faults,
                duration, false, std::move(watch)};
  return run_hil(s);
}

class HilVm : public ::testing::Test {
 protected:
  void SetUp() override {
    if (if_nametoindex("vcan0") == 0 || sim_line(0).empty()) {
      GTEST_SKIP() << "no vcan0 or gpio-sim chip: this runs inside the HIL VM (scripts/hil-vm.sh)";
    }
  }
};

// Nominal: the Table 4 sine over vcan0; the enable line on gpio-sim goes high in RUN, the
// heartbeat toggles, and both are low again after the stop.
TEST_F(HilVm, Table4SineOverVcanWithGpioSimLines) {
  const std::string enable = sim_line(0);
  const std::string heartbeat = sim_line(2);
  const HilResult r = run("vm_nominal", "", 4.0, [&](ChildProcess&) {
    int enabled = 0;
    int toggles = 0;
    int last = read_value(heartbeat);
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(3);
    while (std::chrono::steady_clock::now() < end) {
      enabled = std::max(enabled, read_value(enable));
      const int h = read_value(heartbeat);
      if (h != last) ++toggles;
      last = h;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));  // sampling the line, not waiting
    }
    return "enable " + std::to_string(enabled) + " toggles " + std::to_string(toggles);
  });
  expect_clean_run(r, 4.0, kRate);
  expect_first_run(r, safety());
  EXPECT_NE(r.observed.find("enable 1"), std::string::npos) << r.observed;
  const auto toggles = find_number(r.observed, R"(toggles (\d+))");
  ASSERT_TRUE(toggles);
  EXPECT_GT(*toggles, 20.0) << "the heartbeat line did not toggle";
  EXPECT_EQ(read_value(enable), 0) << "enable left high after the stop";

  mrd::model::CurrentSchedule schedule;
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i + 1 < r.telemetry.size(); ++i) {
    const auto& row = r.telemetry[i];
    EXPECT_NE(row.state, SupervisorState::kSafe) << transitions(r);
    const double scheduled = schedule.update(row.displacement);
    if (row.in_control() && scheduled != row.scheduled_current) ++mismatches;
  }
  EXPECT_EQ(mismatches, 0u);
}

// The CAN faults, one after the other, each reacting as docs/FIRMWARE.md says.
TEST_F(HilVm, CanFaultsTripTheDocumentedReactions) {
  const HilResult r = run("vm_faults",
                          "[faults.loss]\nkind = \"frame_loss\"\nvalue = 20.0\nstart = 1.5\nduration = 0.5\n"
                          "[faults.crc]\nkind = \"bad_checksum\"\nstart = 2.5\nduration = 0.1\n"
                          "[faults.errors]\nkind = \"error_frames\"\nvalue = 100.0\nstart = 3.5\nduration = 0.5\n"
                          "[faults.driver]\nkind = \"driver_fault\"\nstart = 4.5\nduration = 0.2\n"
                          "[faults.silent]\nkind = \"lvdt_silent\"\nstart = 5.5\nduration = 0.3\n",
                          7.0);
  expect_clean_run(r, 7.0, kRate);
  expect_first_run(r, safety());
  const auto not_fresh = [](const TelemetryRow& x) { return !fresh(x); };
  const auto safe_in = [&](double from, double to) {
    const std::size_t i = first_in(r, SupervisorState::kSafe, from);
    return i < r.telemetry.size() && r.plant_time(r.telemetry[i]) < to ? i : r.telemetry.size();
  };
  // Lost frames: periods without a sample (DEGRADED), never six in a row at 20 %.
  EXPECT_EQ(safe_in(1.5, 2.0), r.telemetry.size()) << transitions(r);
  EXPECT_NE(r.controller_output.find("sequence_gaps="), std::string::npos);
  EXPECT_EQ(r.controller_output.find("sequence_gaps=0 "), std::string::npos) << r.controller_output;
  // Corrupted frames: SAFE (sample_corrupted) after bad_sample_periods.
  const std::size_t crc = safe_in(2.5, 2.6);
  ASSERT_LT(crc, r.telemetry.size()) << transitions(r);
  EXPECT_EQ(r.telemetry[crc].trigger, Trigger::kSampleCorrupted);
  EXPECT_EQ(run_length_before(r.telemetry, crc, [](const TelemetryRow& x) { return x.sample == "corrupted"; }),
            static_cast<std::size_t>(safety().bad_sample_periods));
  // Error frames (error-warning): counted, no reaction.
  EXPECT_EQ(safe_in(3.5, 4.0), r.telemetry.size()) << transitions(r);
  EXPECT_EQ(r.controller_output.find("error_frames=0 "), std::string::npos) << r.controller_output;
  // Driver fault (gpio-sim pull and the feedback frame): SAFE at once.
  const std::size_t driver = safe_in(4.5, 4.7);
  ASSERT_LT(driver, r.telemetry.size()) << transitions(r);
  EXPECT_EQ(r.telemetry[driver].trigger, Trigger::kDriverFault);
  EXPECT_NEAR(r.plant_time(r.telemetry[driver]), 4.5, 0.03);
  // The LVDT falls silent: SAFE (sensor_stale) after more than stale_periods periods.
  const std::size_t silent = safe_in(5.5, 5.8);
  ASSERT_LT(silent, r.telemetry.size()) << transitions(r);
  EXPECT_EQ(r.telemetry[silent].trigger, Trigger::kSensorStale);
  EXPECT_EQ(run_length_before(r.telemetry, silent, not_fresh), static_cast<std::size_t>(safety().stale_periods + 1));
  // And RUN again after each.
  const std::size_t back = first_in(r, SupervisorState::kRun, 5.8);
  ASSERT_LT(back, r.telemetry.size()) << transitions(r);
  expect_recovery_length(r, back, safety());
}

}  // namespace
