#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "config/config_message.hpp"
#include "config/controller_config.hpp"
#include "model/effects/effect_set.hpp"

namespace mrd::plant {

enum class ProfileKind : std::uint8_t { kSine, kSines, kRandom, kPlayback };
[[nodiscard]] std::string_view to_string(ProfileKind k);

// The rig's motion (sim/displacement_profile.hpp).
struct ProfileConfig {
  ProfileKind kind = ProfileKind::kSine;
  double amplitude = 0.040;  // [m], sine, sines; the peak of random
  double frequency = 0.5;    // [Hz], sine
  std::array<double, 5> frequencies{0.05, 0.1, 0.2, 0.5, 1.0};  // [Hz], sines: the paper's five
  int cycles = 2;            // sines: whole cycles at each frequency
  double random_low = 0.1;   // [Hz], random: the band
  double random_high = 2.0;  // [Hz]
  double random_length = 60.0;  // [s], random: the span its peak is scaled over
  std::string file;          // playback: a recorded run (mrd-replay's formats)
};

// What the plant can do wrong, each for a scripted time window. Which bus each applies to is
// in docs/HIL.md; a fault on a bus the plant does not serve does nothing.
enum class FaultKind : std::uint8_t {
  kFrameLoss,       // value: percent of LVDT frames (CAN) / requests (Modbus) lost
  kDelay,           // value: seconds the LVDT frames / Modbus answers come late
  kBadChecksum,     // CAN: LVDT frames with a wrong CRC; Modbus: answers are exceptions
  kBadCounter,      // CAN: LVDT frames repeat the previous rolling counter
  kLvdtFrozen,      // the LVDT value stops at the one it had when the fault began
  kLvdtOutOfRange,  // value: the displacement the LVDT reports [m]
  kLvdtSilent,      // CAN: no LVDT frames; Modbus: LVDT reads get no answer
  kSensorFault,     // CAN: the LVDT frame's SensorFault bit
  kServerStall,     // Modbus: requests are taken but never answered
  kServerRestart,   // Modbus: the server closes every connection and is down for the window
  kErrorFrames,     // CAN: value error frames (controller problem: RX warning) per second
  kBusOff,          // CAN: one bus-off error frame at the start of the window
  kDriverFault,     // the driver's fault: CAN feedback bit, and the gpio-sim pull when set
  kDemandStale,     // the outer controller stops: CAN no Force_Demand frames; Modbus value and counter frozen
  kDemandInvalid,   // CAN: the DemandInvalid bit; Modbus: value [N], beyond force.demand_range, as the demand
  kCount
};
[[nodiscard]] std::string_view to_string(FaultKind k);

// Where a fault's start counts from: the controller's first command (so a script means the
// same however long the controller takes to start), or the plant's own start.
enum class FaultClock : std::uint8_t { kFirstCommand, kStart };

struct Fault {
  std::string name;  // its table: [faults.<name>]
  FaultKind kind = FaultKind::kFrameLoss;
  double start = 0.0;     // [s] on the fault clock
  double duration = 0.0;  // [s]; 0: until the end of the run
  double value = 0.0;     // see FaultKind; 0 takes the kind's default

  [[nodiscard]] bool active(double t) const {
    return t >= start && (duration <= 0.0 || t < start + duration);
  }
};

// The Modbus server side. The register map, slave id and transport are the controller's.
struct ModbusServerConfig {
  bool enabled = true;
  std::string listen;     // TCP address; "": the controller's modbus.tcp.host
  int port = -1;          // -1: the controller's modbus.tcp.port; 0: any free port (printed)
  std::string rtu_link;   // RTU: symlink made to the pty the controller opens; "": modbus.rtu.device
};

// The CAN side. Ids and the interface are the controller's.
struct CanNodeConfig {
  bool enabled = false;
  std::string interface;  // "": the controller's can.interface
  bool feedback = true;   // send Coil_CurrentFeedback frames
  std::string fault_pull;  // sysfs pull file of the gpio-sim fault line ("": none)
};

struct PlantConfig {
  double rate = 1000.0;      // [Hz], steps and LVDT frames
  double duration = 0.0;     // [s]; 0: the profile's length, or until SIGTERM when endless
  std::string controller_config;  // "": the controller's embedded default
  double lvdt_noise = 5e-6;  // RMS [m]
  double force_noise = 0.0;  // load cell RMS [N]
  // The outer controller of force mode: c [N s/m] for a demand of c times the rig's velocity,
  // sent over the bus the controller reads it from; 0 sends none.
  double demand_damping = 0.0;
  std::uint32_t seed = 1;
  std::string log;           // recorded-run CSV ("": none)
  FaultClock faults_from = FaultClock::kFirstCommand;
  // The stepping thread below the controller's default 80, so on a shared host the
  // controller's loop goes first; the bus threads below it.
  runtime::RealtimeConfig realtime{70, -1, true, 60};
  ProfileConfig profile;
  ModbusServerConfig modbus;
  CanNodeConfig can;
  model::EffectSet effects;  // the truth's effects (the controller's observer may lack them)
  std::vector<Fault> faults;

  // The controller's config, read from controller_config: bus layout and base damper.
  config::ControllerConfig controller;

  [[nodiscard]] double period() const { return 1.0 / rate; }
  // The damper the plant simulates: the controller's base model with the plant's effects.
  [[nodiscard]] model::DamperModel truth() const;
  [[nodiscard]] std::string listen_host() const;
  [[nodiscard]] int listen_port() const;
  [[nodiscard]] std::string can_interface() const;
  // True when demand_damping is on and the controller reads its demand from one of our buses.
  [[nodiscard]] bool sends_demand() const {
    return demand_damping > 0.0 && (controller.modbus.registers.has_demand || controller.can.use_demand);
  }
};

struct LoadedPlantConfig {
  PlantConfig config;
  config::ConfigMessages errors;
  config::ConfigMessages warnings;

  [[nodiscard]] bool ok() const { return errors.empty(); }
  [[nodiscard]] std::string report() const;
};

// Parses and validates, like the controller's loader: every problem at once, file:line: key.
// Relative paths in the file (controller_config, profile.file) are relative to its folder.
LoadedPlantConfig load_plant_config_text(std::string_view text, const std::string& file_name);
LoadedPlantConfig load_plant_config_file(const std::string& path);

}  // namespace mrd::plant
