// The TOML config: the default file, good variants, and many bad ones, asserting the messages.
#include "config/config_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/config/config_errors.hpp"
#include "tests/support/test_files.hpp"

namespace {

using mrd::config::DeviceBackend;
using mrd::config::LoadedConfig;
using mrd::config::load_config_file;
using mrd::config::load_config_text;

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string lines_of(const LoadedConfig& c) { return c.report(); }

using mrd::test::has_error;

bool has_error_containing(const LoadedConfig& c, const std::string& key, const std::string& text) {
  for (const auto& e : c.errors) {
    if (e.key == key && e.message.find(text) != std::string::npos) return true;
  }
  return false;
}

TEST(ConfigDefault, TheInstalledFileIsTheEmbeddedOneAndIsValid) {
  const std::string installed = read(MRD_SOURCE_DIR "/etc/mrd/mrd.toml");
  EXPECT_EQ(installed, std::string(mrd::config::default_config_text()));
  const LoadedConfig c = mrd::config::load_default_config();
  EXPECT_TRUE(c.ok()) << lines_of(c);
  EXPECT_TRUE(c.warnings.empty()) << lines_of(c);
  EXPECT_EQ(c.config.rate, 1000.0);
  EXPECT_EQ(c.config.backends.lvdt, DeviceBackend::kMock);
  EXPECT_DOUBLE_EQ(c.config.law.observer.sample_period, 1e-3);
}

TEST(ConfigDefault, StatesEveryKeyTheLoaderKnows) {
  const LoadedConfig c = mrd::config::load_default_config();
  std::string missing;
  for (const auto& k : c.defaulted) missing += k + " ";
  EXPECT_TRUE(c.defaulted.empty()) << "not in etc/mrd/mrd.toml: " << missing;
  EXPECT_GT(c.keys.size(), 100u);
}

TEST(ConfigDefault, EveryKeyIsDocumentedInFirmwareMd) {
  const std::string doc = read(MRD_SOURCE_DIR "/docs/FIRMWARE.md");
  const LoadedConfig c = mrd::config::load_default_config();
  for (const auto& key : c.keys) {
    EXPECT_NE(doc.find("`" + key + "`"), std::string::npos) << key << " is not in docs/FIRMWARE.md";
  }
}

TEST(ConfigDefault, StatedValuesEqualTheCompiledDefaults) {
  // An empty file takes every default from the structs; the default file states them.
  const LoadedConfig empty = load_config_text("", "empty.toml");
  const LoadedConfig file = mrd::config::load_default_config();
  ASSERT_TRUE(empty.ok()) << lines_of(empty);
  const auto& a = empty.config;
  const auto& b = file.config;
  EXPECT_EQ(a.safety.stale_periods, b.safety.stale_periods);
  EXPECT_EQ(a.safety.recovery_periods, b.safety.recovery_periods);
  EXPECT_EQ(a.safety.current_tolerance, b.safety.current_tolerance);
  EXPECT_EQ(a.law.damper.jiles_atherton.k, b.law.damper.jiles_atherton.k);
  EXPECT_EQ(a.law.schedule.thresholds, b.law.schedule.thresholds);
  EXPECT_EQ(a.law.limits.max_current, b.law.limits.max_current);
  EXPECT_EQ(a.modbus.response_timeout, b.modbus.response_timeout);
  EXPECT_EQ(a.modbus.registers.lvdt.scale, b.modbus.registers.lvdt.scale);
  EXPECT_EQ(a.can.lvdt_id, b.can.lvdt_id);
  EXPECT_EQ(a.gpio.heartbeat.offset, b.gpio.heartbeat.offset);
  EXPECT_EQ(a.realtime.priority, b.realtime.priority);
  EXPECT_EQ(a.realtime.io_priority, b.realtime.io_priority);
  EXPECT_EQ(a.telemetry.ring_size, b.telemetry.ring_size);
}

TEST(ConfigGood, TenKilohertzModbusRtuAndGpio) {
  const LoadedConfig c = load_config_text(R"(
[loop]
rate = 10000            # an integer where a float is expected is fine
[backends]
lvdt = "modbus"
driver = "modbus"
lines = "gpio"
[modbus]
transport = "rtu"
response_timeout = 0.004
[modbus.rtu]
device = "/dev/ttyAMA0"
parity = "E"
[modbus.registers]
lvdt_kind = "holding"
lvdt_address = 10
[modbus.registers.lvdt]
type = "float32"
word_order = "low_first"
scale = 0.001
[gpio]
chip = "/dev/gpiochip1"
enable = { offset = 17, active_low = true }
[can]
lvdt_id = 0x18FF0010
extended_ids = true
)",
                                          "good.toml");
  ASSERT_TRUE(c.ok()) << lines_of(c);
  EXPECT_DOUBLE_EQ(c.config.law.observer.sample_period, 1e-4);
  EXPECT_EQ(c.config.backends.lvdt, DeviceBackend::kModbus);
  EXPECT_EQ(c.config.modbus.rtu.parity, 'E');
  EXPECT_EQ(c.config.modbus.response_timeout, std::chrono::microseconds{4000});
  EXPECT_EQ(c.config.modbus.registers.lvdt.type, mrd::hal::modbus::RegisterType::kFloat32);
  EXPECT_EQ(c.config.modbus.registers.lvdt.word_order, mrd::hal::modbus::WordOrder::kLowFirst);
  EXPECT_EQ(c.config.gpio.enable.offset, 17);
  EXPECT_TRUE(c.config.gpio.enable.active_low);
  EXPECT_EQ(c.config.can.lvdt_id, 0x18FF0010u);
}

TEST(ConfigBad, MessageHasFileLineKeyAndValue) {
  const LoadedConfig c = load_config_text("[safety]\n\nstale_periods = 0\n", "mrd.toml");
  ASSERT_EQ(c.errors.size(), 1u) << lines_of(c);
  EXPECT_EQ(c.errors[0].to_string(), "mrd.toml:3: safety.stale_periods: must be >= 1, got 0");
}

TEST(ConfigBad, TruncatedFileIsOneSyntaxErrorWithItsLine) {
  const std::string full(mrd::config::default_config_text());
  const std::string cut = full.substr(0, full.find("type = \"int32\"") + 10);  // `type = "in`
  const LoadedConfig c = load_config_text(cut, "cut.toml");
  ASSERT_EQ(c.errors.size(), 1u) << lines_of(c);
  const int line = 1 + static_cast<int>(std::count(cut.begin(), cut.end(), '\n'));
  EXPECT_EQ(c.errors[0].line, line);
  EXPECT_NE(c.errors[0].message.find("TOML syntax error"), std::string::npos);
}

TEST(ConfigBad, WrongTypesAreErrorsNamingBothTypes) {
  const LoadedConfig c = load_config_text(R"([safety]
stale_periods = "5"
enable_in_safe = 1
recovery_periods = 200.0
[loop]
rate = "fast"
[schedule]
currents = [0.0, 0.2, "0.4", 0.6, 0.8, 1.2]
[gpio]
enable = 3
)",
                                          "types.toml");
  EXPECT_TRUE(has_error(c, "types.toml:2: safety.stale_periods: must be an integer, got a string"))
      << lines_of(c);
  EXPECT_TRUE(has_error(c, "types.toml:3: safety.enable_in_safe: must be true or false, got an integer"))
      << lines_of(c);
  EXPECT_TRUE(has_error(c, "types.toml:4: safety.recovery_periods: must be an integer, got a float"))
      << lines_of(c);
  EXPECT_TRUE(has_error(c, "types.toml:6: loop.rate: must be a number, got a string")) << lines_of(c);
  EXPECT_TRUE(has_error(c, "types.toml:8: schedule.currents[2]: must be a number, got a string"))
      << lines_of(c);
  EXPECT_TRUE(has_error(c, "types.toml:10: gpio.enable: must be a table, got an integer")) << lines_of(c);
  EXPECT_EQ(c.errors.size(), 6u) << lines_of(c);
}

TEST(ConfigBad, UnknownKeysAndTablesAreErrorsWithASuggestion) {
  const LoadedConfig c = load_config_text(R"([safety]
stale_period = 5
[saftey]
x = 1
[modbus.registers.lvdt]
scael = 1e-6
[telemetry]
colour = "blue"
)",
                                          "typo.toml");
  EXPECT_TRUE(has_error(c, "typo.toml:2: safety.stale_period: unknown key (did you mean \"stale_periods\"?)"))
      << lines_of(c);
  EXPECT_TRUE(has_error(c, "typo.toml:3: saftey: unknown table (did you mean \"safety\"?)")) << lines_of(c);
  EXPECT_TRUE(has_error(c, "typo.toml:6: modbus.registers.lvdt.scael: unknown key (did you mean \"scale\"?)"))
      << lines_of(c);
  EXPECT_TRUE(has_error(c, "typo.toml:8: telemetry.colour: unknown key")) << lines_of(c);
  EXPECT_EQ(c.errors.size(), 4u) << lines_of(c);
}

TEST(ConfigBad, OutOfPhysicsValuesAreReportedAllAtOnce) {
  const LoadedConfig c = load_config_text(R"([damper.jiles_atherton]
Ms = -1.0
c = 1.0
[damper.fluid]
volume_fraction = 0.9
[damper.geometry]
gap = 0.2
[schedule]
thresholds = [0.005, 0.004, 0.020, 0.030, 0.040]
currents = [0.0, 0.2, 0.4, 0.6, 0.8, 2.0]
[compensator]
slew_rate = 0
[loop]
rate = 5
)",
                                          "physics.toml");
  EXPECT_TRUE(has_error_containing(c, "damper.jiles_atherton.Ms", "(0, 1e+07]")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "damper.jiles_atherton.c", "[0, 1)")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "damper.fluid.volume_fraction", "0.74")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "damper.geometry.gap", "(0, 0.01]")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "schedule.thresholds[1]", "increase")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "schedule.currents[5]", "compensator.max_current")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "compensator.slew_rate", "> 0")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "loop.rate", "10..20000")) << lines_of(c);
  // Each names the line of its key; an indexed key names its array's line.
  for (const auto& e : c.errors) EXPECT_GT(e.line, 0) << e.to_string();
  EXPECT_TRUE(has_error(c, "physics.toml:9: schedule.thresholds[1]: thresholds must increase strictly"))
      << lines_of(c);

  // Micrometres written where metres belong.
  const LoadedConfig um = load_config_text("[damper.fluid]\nparticle_diameter = 1.5\n", "um.toml");
  EXPECT_TRUE(has_error(um, "um.toml:2: damper.fluid.particle_diameter: must be given in metres (MR "
                            "particles are 0.1-100 um)"))
      << lines_of(um);
}

// A value past physics is an error, not a warning and a NaN at run time; numbers print as %g
// (not 309 digits of %f), and a bad rate is reported as itself, not as its -inf period.
TEST(ConfigBad, EveryModelParameterHasAPhysicalBoundInPlainNumbers) {
  const LoadedConfig c = load_config_text(R"([damper.jiles_atherton]
Ms = 1e308
a = 2e6
alpha = 1.5
k = 1e300
[damper.circuit]
turns = 1e9
effective_length = 100.0
[damper.fluid]
viscosity = 1e4
particle_saturation = 30.0
[damper.geometry]
piston_area = 2.0
pole_length = 5.0
piston_diameter = 3.0
sign_velocity_scale = 10.0
seal_friction = 1e9
[loop]
rate = -0.0
)",
                                          "bounds.toml");
  for (const char* line :
       {"bounds.toml:2: damper.jiles_atherton.Ms: must lie in (0, 1e+07], got 1e+308",
        "bounds.toml:3: damper.jiles_atherton.a: must lie in (0, 1e+06], got 2e+06",
        "bounds.toml:4: damper.jiles_atherton.alpha: must lie in [0, 1], got 1.5",
        "bounds.toml:5: damper.jiles_atherton.k: must lie in (0, 1e+06], got 1e+300",
        "bounds.toml:7: damper.circuit.turns: must lie in (0, 1e+06], got 1e+09",
        "bounds.toml:8: damper.circuit.effective_length: must lie in (0, 10], got 100",
        "bounds.toml:10: damper.fluid.viscosity: must lie in (0, 1000], got 10000",
        "bounds.toml:11: damper.fluid.particle_saturation: must lie in (0, 3], got 30",
        "bounds.toml:13: damper.geometry.piston_area: must lie in (0, 1], got 2",
        "bounds.toml:14: damper.geometry.pole_length: must lie in (0, 1], got 5",
        "bounds.toml:15: damper.geometry.piston_diameter: must lie in (0, 1], got 3",
        "bounds.toml:16: damper.geometry.sign_velocity_scale: must lie in (0, 1], got 10",
        "bounds.toml:17: damper.geometry.seal_friction: must lie in [0, 1e+07], got 1e+09",
        "bounds.toml:19: loop.rate: must be in 10..20000 Hz, got -0"}) {
    EXPECT_TRUE(has_error(c, line)) << line << "\n" << lines_of(c);
  }
  EXPECT_EQ(c.errors.size(), 14u) << lines_of(c);
  EXPECT_TRUE(c.warnings.empty()) << lines_of(c);
  // The largest sane values pass.
  EXPECT_TRUE(load_config_text("[damper.jiles_atherton]\nMs = 1e7\na = 1e6\nalpha = 1e-6\nk = 1e6\n", "edge.toml").ok());
}

// The current feedback in the LVDT's registers reads one word of the other: a negative
// displacement decoded as 65.5 mm minus its size (found by mrd-controller --probe against
// mrd-plant, when the struct's default address was 0 and the file's 2).
TEST(ConfigBad, CurrentFeedbackOverlappingTheLvdtOrTheSetpoint) {
  const std::string head = "[backends]\nlvdt = \"modbus\"\ndriver = \"modbus\"\n[modbus.registers]\n"
                           "has_current_feedback = true\n";
  EXPECT_TRUE(load_config_text(head, "ok.toml").ok()) << "the default feedback address is past the LVDT";
  const LoadedConfig lvdt = load_config_text(head + "current_feedback_address = 1\n", "f.toml");
  EXPECT_TRUE(has_error_containing(lvdt, "modbus.registers.current_feedback_address", "overlaps the LVDT's registers"))
      << lines_of(lvdt);
  const LoadedConfig setpoint =
      load_config_text(head + "current_feedback_kind = \"holding\"\ncurrent_feedback_address = 0\n", "f.toml");
  EXPECT_TRUE(has_error_containing(setpoint, "modbus.registers.current_feedback_address", "overlaps the setpoint's"))
      << lines_of(setpoint);
}

TEST(ConfigBad, BadRegisterMaps) {
  const LoadedConfig c = load_config_text(R"([backends]
lvdt = "modbus"
driver = "modbus"
[modbus]
slave_id = 0
response_timeout = 0
[modbus.tcp]
port = 70000
[modbus.registers]
lvdt_kind = "holding"
lvdt_address = 65535
setpoint_address = 65535
[modbus.registers.lvdt]
type = "int64"
byte_order = "little"
[modbus.registers.setpoint]
scale = 0
)",
                                          "regs.toml");
  EXPECT_TRUE(has_error(c, "regs.toml:14: modbus.registers.lvdt.type: must be one of int16, uint16, "
                           "int32, uint32, float32, got \"int64\""))
      << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "modbus.registers.lvdt.byte_order", "normal, swapped")) << lines_of(c);
  EXPECT_TRUE(has_error(c, "regs.toml:11: modbus.registers.lvdt_address: must be in 0..65535 (all "
                           "words of the value)"))
      << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "modbus.registers.setpoint.scale", "")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "modbus.registers.setpoint_address", "overlaps")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "modbus.slave_id", "1..247")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "modbus.response_timeout", "> 0")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "modbus.tcp.port", "1..65535")) << lines_of(c);
}

TEST(ConfigBad, CanIdsAndGpioLines) {
  const LoadedConfig c = load_config_text(R"([can]
lvdt_id = 0x800
command_id = 0x211
feedback_id = 0x211
interface = ""
[gpio]
fault = { offset = 0 }
consumer_prefix = "a-very-long-consumer-prefix"
)",
                                          "can.toml");
  EXPECT_TRUE(has_error_containing(c, "can.lvdt_id", "11 bits")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "can.feedback_id", "must differ")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "can.interface", "interface name")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "gpio.fault.offset", "enable.offset")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "gpio.consumer_prefix", "1..21")) << lines_of(c);
  EXPECT_EQ(c.errors.size(), 5u) << lines_of(c);
}

// Found by fuzz_config: a decimation of 0 made the ring's cross-check convert an infinite record
// count to an integer (undefined behaviour). The decimation's own error is the only message.
TEST(ConfigBad, ZeroDecimationIsOneErrorAndNoInfiniteRecordCount) {
  const LoadedConfig c = load_config_text("[telemetry]\ndecimation = 0\nring_size = 8192\n", "d.toml");
  EXPECT_TRUE(has_error(c, "d.toml:2: telemetry.decimation: must be >= 1, got 0")) << lines_of(c);
  EXPECT_EQ(c.errors.size(), 1u) << lines_of(c);
  EXPECT_EQ(c.report().find("telemetry.ring_size"), std::string::npos) << lines_of(c);
}

TEST(ConfigBad, SafetyAndTelemetryAndRealtime) {
  const LoadedConfig c = load_config_text(R"([safety]
fail_safe_current = 0.4
displacement_max = 0.03
[realtime]
priority = 120
[telemetry]
decimation = 0
ring_size = 4
[backends]
lines = "spi"
)",
                                          "s.toml");
  EXPECT_TRUE(has_error_containing(c, "safety.fail_safe_current", "enable_in_safe")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "simulation.amplitude", "displacement_min..max")) << lines_of(c);
  EXPECT_TRUE(has_error(c, "s.toml:5: realtime.priority: must be in 0..99 (0: no SCHED_FIFO), got 120"))
      << lines_of(c);
  EXPECT_TRUE(has_error(c, "s.toml:7: telemetry.decimation: must be >= 1, got 0")) << lines_of(c);
  EXPECT_TRUE(has_error_containing(c, "telemetry.ring_size", "16..")) << lines_of(c);
  EXPECT_TRUE(has_error(c, "s.toml:10: backends.lines: must be one of mock, gpio, got \"spi\"")) << lines_of(c);
  // The 30 mm range no longer reaches past the 40 mm threshold: a warning, not an error.
  ASSERT_EQ(c.warnings.size(), 1u) << lines_of(c);
  EXPECT_EQ(c.warnings[0].key, "safety.displacement_max");
}

TEST(ConfigBad, BusThreadPriorityStaysBelowTheLoop) {
  const LoadedConfig above = load_config_text("[realtime]\npriority = 50\nio_priority = 50\n", "r.toml");
  EXPECT_TRUE(has_error(above, "r.toml:3: realtime.io_priority: must be below realtime.priority (50): a bus "
                               "thread must not preempt the loop, got 50"))
      << lines_of(above);
  const LoadedConfig range = load_config_text("[realtime]\nio_priority = -1\n", "r.toml");
  EXPECT_TRUE(has_error_containing(range, "realtime.io_priority", "0..99")) << lines_of(range);
  // A loop under SCHED_OTHER leaves the bus threads there too, whatever io_priority says.
  EXPECT_TRUE(load_config_text("[realtime]\npriority = 0\n", "r.toml").ok());
}

TEST(ConfigFile, MissingFileAndFileNameInMessages) {
  const LoadedConfig missing = load_config_file("/nonexistent/mrd.toml");
  ASSERT_EQ(missing.errors.size(), 1u);
  EXPECT_EQ(missing.errors[0].to_string(), "/nonexistent/mrd.toml: cannot open the file: No such file or directory");

  const auto path = std::filesystem::temp_directory_path() / "mrd_config_test.toml";
  std::ofstream(path) << "[backends]\nlvdt = \"mock\"\ndriver = \"mock\"\nlines = \"mock\"\n[loop]\nrate = 0.5\n";
  const LoadedConfig c = load_config_file(path.string());
  ASSERT_EQ(c.errors.size(), 1u) << lines_of(c);
  EXPECT_EQ(c.errors[0].to_string().rfind(path.string() + ":6: loop.rate: must be in 10..20000 Hz", 0), 0u)
      << lines_of(c);
  std::filesystem::remove(path);
}

// An empty or truncated file must not mean "simulate": every back end is named, the demand's in
// force mode too; the embedded default names its mock ones.
TEST(ConfigFile, AFileMustNameItsBackEnds) {
  const mrd::test::TestDirectory dir("mrd_config_backends");
  const auto empty = dir / "empty.toml";
  std::ofstream(empty) << "";
  const LoadedConfig c = load_config_file(empty.string());
  EXPECT_EQ(lines_of(c), empty.string() + ": backends.lvdt: must be named (mock | modbus | can): a file without it "
                                          "would run the simulation and drive nothing\n" +
                             empty.string() + ": backends.driver: must be named (mock | modbus | can): a file without "
                                              "it would run the simulation and drive nothing\n" +
                             empty.string() + ": backends.lines: must be named (mock | gpio): a file without it would "
                                              "run the simulation and drive nothing\n");
  const auto force = dir / "force.toml";
  std::ofstream(force) << "[control]\nmode = \"force\"\n[backends]\nlvdt = \"mock\"\ndriver = \"mock\"\nlines = \"mock\"\n";
  const LoadedConfig f = load_config_file(force.string());
  ASSERT_EQ(f.errors.size(), 1u) << lines_of(f);
  EXPECT_EQ(f.errors[0].key, "backends.demand");
  const auto named = dir / "named.toml";
  std::ofstream(named) << "[backends]\nlvdt = \"mock\"\ndriver = \"mock\"\nlines = \"mock\"\n";
  EXPECT_TRUE(load_config_file(named.string()).ok()) << lines_of(load_config_file(named.string()));
  EXPECT_TRUE(mrd::config::load_default_config().ok());
}

TEST(ConfigOverride, RevalidateChecksCommandLineChanges) {
  auto config = mrd::config::load_default_config().config;
  config.rate = 10000.0;
  auto c = mrd::config::revalidate(config, "command line");
  EXPECT_TRUE(c.ok()) << lines_of(c);
  EXPECT_DOUBLE_EQ(c.config.law.observer.sample_period, 1e-4);
  config.rate = 1e6;
  c = mrd::config::revalidate(config, "command line");
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.errors[0].to_string().rfind("command line: loop.rate:", 0), 0u) << lines_of(c);
}

}  // namespace
