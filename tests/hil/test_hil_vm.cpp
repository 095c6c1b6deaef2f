// Hardware-in-the-loop over the kernel's own interfaces, inside the HIL VM (scripts/hil-vm.sh):
// mrd-controller and mrd-plant over vcan0 with the DBC's frames, the libgpiod back end on a
// gpio-sim chip, and the CAN faults. The controller runs at 25 Hz and the plant at 100 Hz (four
// LVDT frames per period, so the two clocks never beat, and a plant late by less than three
// frames costs no sample): the VM emulates its CPU (TCG), and on a busy host it stalls for tens
// of milliseconds now and then. Reactions are counted in periods the loop ran (telemetry rows),
// as the supervisor counts them; fault windows are on the plant's fault clock, which starts at
// the controller's first command.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <net/if.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "config/config_loader.hpp"
#include "tests/hil/hil_checks.hpp"

namespace {

using namespace mrd::test;
using namespace std::chrono_literals;
constexpr double kRate = 25.0;
constexpr double kPeriod = 1.0 / kRate;
// Rows between a fault's scripted start and the row that reacts, beyond the reaction's own
// count: the fault clock's origin (a plant step, 10 ms) and the phase of the two loops. The
// counts themselves are checked exactly.
constexpr std::size_t kSlack = 2;

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

// A line's sysfs value, opened once and re-read with pread: cheap enough to sample every few
// milliseconds under TCG without starving the guest.
class LineValue {
 public:
  explicit LineValue(const std::string& line) : fd_(open((line + "/value").c_str(), O_RDONLY | O_CLOEXEC)) {}
  ~LineValue() {
    if (fd_ >= 0) close(fd_);
  }
  LineValue(const LineValue&) = delete;
  LineValue& operator=(const LineValue&) = delete;
  int read() const {
    char c = 0;
    return fd_ >= 0 && pread(fd_, &c, 1, 0) == 1 ? c - '0' : -1;
  }

 private:
  int fd_;
};

void pull(const std::string& line, bool up) { std::ofstream(line + "/pull") << (up ? "pull-up" : "pull-down"); }

// Lines as in mrd.toml's [gpio]: enable 0, fault 1, heartbeat 2.
const std::string& enable_line() {
  static const std::string s = sim_line(0);
  return s;
}
const std::string& fault_line() {
  static const std::string s = sim_line(1);
  return s;
}
const std::string& heartbeat_line() {
  static const std::string s = sim_line(2);
  return s;
}

std::string controller_toml() {
  return "[loop]\nrate = 25.0\n[backends]\nlvdt = \"can\"\ndriver = \"can\"\nlines = \"gpio\"\n"
         "[can]\ninterface = \"vcan0\"\n[gpio]\nchip = \"gpiochip0\"\n"
         "[safety]\noverrun_limit = 1000000\nrecovery_periods = 10\nfrozen_periods = 4\n";
}

const mrd::config::ControllerConfig& controller() {
  static const auto config = mrd::config::load_config_text(controller_toml(), "vm").config;
  return config;
}
const mrd::control::SupervisorConfig& safety() { return controller().safety; }

HilResult run(const std::string& name, const std::string& faults, double duration,
              std::function<std::string(ChildProcess&)> watch = {}) {
  HilScenario s{name, controller_toml(),
                "rate = 100.0\n[modbus]\nenabled = false\n[can]\nenabled = true\n"
                "[profile]\nkind = \"sine\"\namplitude = 0.040\nfrequency = 0.5\n" +
                    faults,
                duration, false, std::move(watch)};
  return run_hil(s);
}

double monotonic_now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// The first row at or after fault time t where the supervisor enters `state`.
std::size_t entry_into(const HilResult& r, mrd::control::SupervisorState state, double t) {
  for (std::size_t i = 1; i < r.telemetry.size(); ++i) {
    if (r.fault_time(r.telemetry[i]) >= t && r.telemetry[i].state == state && r.telemetry[i - 1].state != state) {
      return i;
    }
  }
  return r.telemetry.size();
}

// Rows (periods the loop ran) from the first at or after fault time t up to row i, inclusive.
std::size_t rows_since(const HilResult& r, double t, std::size_t i) {
  std::size_t n = 0;
  for (std::size_t k = 0; k <= i && k < r.telemetry.size(); ++k) n += r.fault_time(r.telemetry[k]) >= t;
  return n;
}

bool ever_in(const HilResult& r, mrd::control::SupervisorState state, double from, double to) {
  for (const auto& row : r.telemetry) {
    const double t = r.fault_time(row);
    if (t >= from && t < to && row.state == state) return true;
  }
  return false;
}

std::uint64_t counter(const std::string& output, const std::string& name) {
  return static_cast<std::uint64_t>(find_number(output, "[ :]" + name + R"(=(\d+))").value_or(0.0));
}

class HilVm : public ::testing::Test {
 protected:
  void SetUp() override {
    if (if_nametoindex("vcan0") == 0 || enable_line().empty()) {
      GTEST_SKIP() << "no vcan0 or gpio-sim chip: this runs inside the HIL VM (scripts/hil-vm.sh)";
    }
  }
};

// What the watcher saw on the gpio-sim lines, in order.
struct LineWatch {
  bool enabled = false;      // enable went high (RUN)
  int toggles_before = 0;    // heartbeat toggles before the fault pull
  double pulled_at = 0.0;    // CLOCK_MONOTONIC of the pull-up [s]
  double released_at = 0.0;  // and of the pull-down
  bool dropped = false;      // enable went low after the pull
  int toggles_while_off = 0;
  bool reenabled = false;    // enable high again after the pull-down
};

// Nominal: the Table 4 sine over vcan0 with the lines on gpio-sim. Enable goes high in RUN and
// the heartbeat toggles; a pull-up on the fault line (a driver fault) drops enable at the next
// period, SAFE (driver_fault); released, RUN again after recovery_periods.
TEST_F(HilVm, Table4SineOverVcanWithGpioSimLinesAndAFaultPull) {
  pull(fault_line(), false);
  LineWatch w;
  const HilResult r = run("vm_nominal", "", 5.0, [&](ChildProcess& controller) {
    const auto limit = std::chrono::steady_clock::now() + 60s;
    const LineValue enable_value(enable_line());
    const LineValue heartbeat_value(heartbeat_line());
    int last = heartbeat_value.read();
    // Paced by the controller's output (5 ms at most per look), until it exits.
    while (controller.read_for(5ms) && std::chrono::steady_clock::now() < limit) {
      // Heartbeat first: the controller writes enable before it toggles the heartbeat, so a
      // toggle seen here comes with the enable that went with it.
      const int h = heartbeat_value.read();
      const int enable = enable_value.read();
      const bool toggled = h != last;
      last = h;
      if (!w.enabled) {
        w.enabled = enable == 1;
      } else if (w.pulled_at == 0.0) {
        w.toggles_before += toggled;
        if (w.toggles_before >= 20) {
          pull(fault_line(), true);
          w.pulled_at = monotonic_now();  // after the write: the line is high from here on
        }
      } else if (!w.dropped) {
        if (enable == 0) {
          w.dropped = true;
          pull(fault_line(), false);
          w.released_at = monotonic_now();
        }
      } else if (!w.reenabled) {
        w.reenabled = enable == 1;
        if (!w.reenabled) w.toggles_while_off += toggled;
      }
    }
    return std::string();
  });
  pull(fault_line(), false);
  SCOPED_TRACE(diagnosis(r));
  expect_clean_run(r, 5.0, kRate);
  expect_first_run(r, safety());
  EXPECT_TRUE(w.enabled) << "enable never went high on gpio-sim";
  EXPECT_GE(w.toggles_before, 20) << "the heartbeat line did not toggle";
  ASSERT_GT(w.pulled_at, 0.0);
  EXPECT_TRUE(w.dropped) << "the fault pull did not drop enable";
  EXPECT_EQ(w.toggles_while_off, 0) << "heartbeat toggled outside control";
  EXPECT_TRUE(w.reenabled) << "enable never came back after the fault was released";
  EXPECT_EQ(read_value(enable_line()), 0) << "enable left high after the stop";

  // SAFE (driver_fault) in the first or second period after the pull (a row's time is its
  // release; the line is read just after it); the only SAFE before the shutdown.
  const double pulled = w.pulled_at - r.controller_t0;  // telemetry time
  const auto rows_after = [&](double t, std::size_t i) {
    std::size_t n = 0;
    for (std::size_t k = 0; k <= i; ++k) n += r.telemetry[k].time > t - kPeriod;
    return n;
  };
  std::size_t safe = r.telemetry.size();
  for (std::size_t i = 1; i + 1 < r.telemetry.size(); ++i) {
    if (r.telemetry[i].state != mrd::control::SupervisorState::kSafe || r.telemetry[i - 1].state == mrd::control::SupervisorState::kSafe) continue;
    EXPECT_EQ(safe, r.telemetry.size()) << "a second SAFE:\n" << transitions(r);
    safe = i;
  }
  ASSERT_LT(safe, r.telemetry.size()) << transitions(r);
  EXPECT_EQ(r.telemetry[safe].trigger, mrd::control::Trigger::kDriverFault) << transitions(r);
  EXPECT_GE(rows_after(pulled, safe), 1u);
  EXPECT_LE(rows_after(pulled, safe), kSlack) << transitions(r);
  const std::size_t back = entry_into(r, mrd::control::SupervisorState::kRun, r.fault_time(r.telemetry[safe]));
  ASSERT_LT(back, r.telemetry.size()) << transitions(r);
  // RUN again after recovery_periods good periods once the line is released (the watcher
  // releases it when it sees enable drop): the run of fresh periods since the release.
  const double released = w.released_at - r.controller_t0;
  const auto m = static_cast<std::size_t>(safety().recovery_periods);
  const std::size_t good = run_length_before(
      r.telemetry, back, [&](const TelemetryRow& x) { return fresh(x) && x.time > released - kPeriod; });
  EXPECT_GE(good, m) << transitions(r);
  EXPECT_LE(good, m + kSlack) << transitions(r);

  EXPECT_GT(expect_table4_followed(r), 50u);
  double top = 0.0;
  for (const double i : r.plant_log.coil) top = std::max(top, i);
  EXPECT_GT(top, 0.8) << "the plant never saw the upper levels' current";
}

// The CAN faults one after the other, each with the reaction docs/FIRMWARE.md gives it and RUN
// again after; the driver fault here is the feedback frame's bit alone (no gpio pull).
TEST_F(HilVm, CanFaultsTripTheDocumentedReactions) {
  const int stale = safety().stale_periods;
  const HilResult r = run("vm_faults",
                          "[faults.loss]\nkind = \"frame_loss\"\nvalue = 20.0\nstart = 1.0\nduration = 0.6\n"
                          "[faults.crc]\nkind = \"bad_checksum\"\nstart = 2.0\nduration = 0.2\n"
                          "[faults.errors]\nkind = \"error_frames\"\nvalue = 100.0\nstart = 3.0\nduration = 0.5\n"
                          "[faults.driver]\nkind = \"driver_fault\"\nstart = 4.0\nduration = 0.1\n"
                          "[faults.silent]\nkind = \"lvdt_silent\"\nstart = 5.0\nduration = 0.4\n"
                          "[faults.counter]\nkind = \"bad_counter\"\nstart = 6.5\nduration = 0.4\n"
                          "[faults.busoff]\nkind = \"bus_off\"\nstart = 8.0\nduration = 0.1\n"
                          "[faults.frozen]\nkind = \"lvdt_frozen\"\nstart = 9.8\nduration = 0.5\n",
                          11.3);
  SCOPED_TRACE(diagnosis(r));
  expect_clean_run(r, 11.3, kRate);
  expect_first_run(r, safety());
  ASSERT_NE(r.plant_output.find("the first command"), std::string::npos) << r.plant_output;
  // RUN again after recovery_periods good periods from the fault's end (a driver fault leaves
  // the samples fresh, so the count starts at the end, not at the SAFE row).
  const auto expect_back_in_run = [&](std::size_t safe, double end) {
    const std::size_t back = entry_into(r, mrd::control::SupervisorState::kRun, r.fault_time(r.telemetry[safe]));
    ASSERT_LT(back, r.telemetry.size()) << transitions(r);
    const auto m = static_cast<std::size_t>(safety().recovery_periods);
    const std::size_t good = run_length_before(
        r.telemetry, back, [&](const TelemetryRow& x) { return fresh(x) && r.fault_time(x) > end - kPeriod; });
    EXPECT_GE(good, m) << end << "\n" << transitions(r);
    EXPECT_LE(good, m + kSlack) << end << "\n" << transitions(r);
  };
  ASSERT_FALSE(ever_in(r, mrd::control::SupervisorState::kSafe, 0.8, 2.0)) << transitions(r);

  // Lost frames (20 %): gaps counted, never six periods without a sample, so no SAFE.
  EXPECT_GT(counter(r.controller_output, "sequence_gaps"), 0u) << r.controller_output;

  // Corrupted frames: SAFE (sample_corrupted) at the bad_sample_periods-th corrupted period.
  const std::size_t crc = entry_into(r, mrd::control::SupervisorState::kSafe, 2.0);
  ASSERT_LT(crc, r.telemetry.size()) << transitions(r);
  EXPECT_EQ(r.telemetry[crc].trigger, mrd::control::Trigger::kSampleCorrupted) << transitions(r);
  EXPECT_LE(rows_since(r, 2.0, crc), static_cast<std::size_t>(safety().bad_sample_periods) + kSlack);
  EXPECT_EQ(run_length_before(r.telemetry, crc, [](const TelemetryRow& x) { return x.sample == "corrupted"; }),
            static_cast<std::size_t>(safety().bad_sample_periods));
  EXPECT_GT(counter(r.controller_output, "bad_checksum"), 0u);
  expect_back_in_run(crc, 2.2);

  // Error frames (RX warning): counted, no reaction.
  EXPECT_FALSE(ever_in(r, mrd::control::SupervisorState::kSafe, 3.0, 4.0)) << transitions(r);
  EXPECT_GE(counter(r.controller_output, "error_frames"), 40u) << r.controller_output;

  // The feedback frame's DriverFault bit: SAFE at the next period.
  const std::size_t driver = entry_into(r, mrd::control::SupervisorState::kSafe, 4.0);
  ASSERT_LT(driver, r.telemetry.size()) << transitions(r);
  EXPECT_EQ(r.telemetry[driver].trigger, mrd::control::Trigger::kDriverFault) << transitions(r);
  EXPECT_LE(rows_since(r, 4.0, driver), kSlack) << transitions(r);
  expect_back_in_run(driver, 4.1);

  // The LVDT falls silent, then its frames repeat their counter (stale copies, dropped): SAFE
  // (sensor_stale) at the period after stale_periods without a fresh sample.
  for (const auto& [start, end] : {std::pair{5.0, 5.4}, std::pair{6.5, 6.9}}) {
    const std::size_t safe = entry_into(r, mrd::control::SupervisorState::kSafe, start);
    ASSERT_LT(safe, r.telemetry.size()) << transitions(r);
    EXPECT_EQ(r.telemetry[safe].trigger, mrd::control::Trigger::kSensorStale) << start << "\n" << transitions(r);
    EXPECT_EQ(run_length_before(r.telemetry, safe, no_sample), static_cast<std::size_t>(stale + 1)) << start;
    EXPECT_LE(rows_since(r, start, safe), static_cast<std::size_t>(stale + 1) + kSlack) << start << "\n" << transitions(r);
    expect_back_in_run(safe, end);
  }
  EXPECT_GT(counter(r.controller_output, "repeated_counter"), 0u) << r.controller_output;

  // Bus-off: no command goes out until bus_off_hold_off after the next good frame, so the
  // writes fail: SAFE (setpoint_write_failed) after write_failure_periods; RUN after the hold-off.
  const std::size_t off = entry_into(r, mrd::control::SupervisorState::kSafe, 8.0);
  ASSERT_LT(off, r.telemetry.size()) << transitions(r);
  EXPECT_EQ(r.telemetry[off].trigger, mrd::control::Trigger::kSetpointWriteFailed) << transitions(r);
  EXPECT_LE(rows_since(r, 8.0, off), static_cast<std::size_t>(safety().write_failure_periods) + kSlack) << transitions(r);
  EXPECT_EQ(counter(r.controller_output, "bus_off"), 1u) << r.controller_output;
  EXPECT_GT(counter(r.controller_output, "tx_inhibited"), 0u) << r.controller_output;
  const std::size_t resumed = entry_into(r, mrd::control::SupervisorState::kRun, 8.0);
  ASSERT_LT(resumed, r.telemetry.size()) << transitions(r);
  const double hold_off = std::chrono::duration<double>(controller().can.bus_off_hold_off).count();
  EXPECT_GE(r.fault_time(r.telemetry[resumed]), 8.0 + hold_off + (safety().recovery_periods - 1) * kPeriod)
      << transitions(r);

  // A frozen LVDT: its frames keep coming, fresh, with one value. With frozen_periods = 4 the
  // 5th repeat is frozen, a bad sample: SAFE (sample_frozen) at the bad_sample_periods-th.
  const int repeats = safety().frozen_periods;
  const std::size_t frozen = entry_into(r, mrd::control::SupervisorState::kSafe, 9.8);
  ASSERT_LT(frozen, r.telemetry.size()) << transitions(r);
  EXPECT_EQ(r.telemetry[frozen].trigger, mrd::control::Trigger::kSampleFrozen) << transitions(r);
  EXPECT_EQ(run_length_before(r.telemetry, frozen, [](const TelemetryRow& x) { return x.sample == "frozen"; }),
            static_cast<std::size_t>(safety().bad_sample_periods));
  // The first frozen frame still differs from the value the loop held: it is no repeat.
  EXPECT_LE(rows_since(r, 9.8, frozen), static_cast<std::size_t>(1 + repeats + safety().bad_sample_periods) + kSlack)
      << transitions(r);
  // The value it froze at is the one the loop held; the rig went on moving.
  const double frozen_value = r.telemetry[frozen].displacement;
  double moved = 0.0;
  for (std::size_t i = 0; i < r.plant_log.time.size(); ++i) {
    const double t = r.plant_log.time[i] - r.fault_origin;
    if (t >= 9.8 && t < 10.3) moved = std::max(moved, std::fabs(r.plant_log.displacement[i] - frozen_value));
  }
  EXPECT_GT(moved, 0.005) << "the rig did not move while the LVDT was frozen";
  expect_back_in_run(frozen, 10.3);

  expect_table4_followed(r);
}

// Force mode over vcan0: the plant is the outer controller and sends Force_Demand (c v) with
// the LVDT frames; 1 s after the first command it falls silent (demand_stale: no Force_Demand
// frames, the LVDT's go on). The controller reaches RUN on the demand and goes SAFE
// (demand_stale) within demand_max_age + 1 periods of the last fresh demand.
TEST_F(HilVm, ForceModeOverVcanTripsSafeWhenTheDemandStops) {
  pull(fault_line(), false);
  std::string toml = "[control]\nmode = \"force\"\n" + controller_toml();
  toml.insert(toml.find("[can]"), "demand = \"can\"\n");  // into [backends]
  const auto loaded = mrd::config::load_config_text(toml, "vm_force");
  ASSERT_TRUE(loaded.ok()) << loaded.report();  // else the limits judged are the defaults
  const auto& force_safety = loaded.config.safety;
  const HilResult r = run_hil({"vm_force_stale", toml,
                               "rate = 100.0\ndemand_damping = 250e3\n[modbus]\nenabled = false\n[can]\nenabled = true\n"
                               "[profile]\nkind = \"sine\"\namplitude = 0.040\nfrequency = 0.5\n"
                               "[faults.quiet]\nkind = \"demand_stale\"\nstart = 1.0\n",
                               2.0, false, {}});
  SCOPED_TRACE(diagnosis(r));
  ASSERT_NO_FATAL_FAILURE(expect_processes_ran(r, mrd::cli::kEndedSafe));
  EXPECT_NE(r.controller_output.find("the run ended in SAFE through demand_stale, not the stop"), std::string::npos);
  const std::size_t run_at = expect_first_run(r, force_safety, fresh_with_demand);
  // The demand was c v, not the idle 0: the sine's peak c v is 31.4 kN.
  double peak = 0.0;
  for (std::size_t i = run_at; i < r.telemetry.size() && r.fault_time(r.telemetry[i]) < 1.0; ++i) {
    peak = std::max(peak, std::fabs(r.telemetry[i].demand));
  }
  EXPECT_GT(peak, 1e3) << "no demand in RUN";
  const std::size_t safe = first_in(r, mrd::control::SupervisorState::kSafe, 0.0);
  ASSERT_LT(safe, r.telemetry.size()) << "never went SAFE\n" << transitions(r);
  ASSERT_GT(safe, run_at) << transitions(r);
  expect_demand_stale_trip(r, safe, force_safety, 1.0, kPeriod);
}

}  // namespace
