#include "tests/hil/hil_run.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>

#include "tests/hil/child_process.hpp"
#include "record/csv.hpp"
#include "record/run_reader.hpp"

namespace mrd::test {

namespace {

using namespace std::chrono_literals;

// The binaries: the build's, or where the environment says (inside the HIL VM).
std::string binary(const char* variable, const char* built) {
  const char* set = std::getenv(variable);
  return set != nullptr ? set : built;
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// A port on 127.0.0.1 nothing listens on now (bound, read, released; libmodbus's listener
// reuses the address).
int free_tcp_port() {
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t size = sizeof a;
  const bool ok = bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
                  getsockname(fd, reinterpret_cast<sockaddr*>(&a), &size) == 0;
  close(fd);
  return ok ? ntohs(a.sin_port) : -1;
}

}  // namespace

HilResult run_hil(const HilScenario& s) {
  HilResult r;
  const auto dir = std::filesystem::temp_directory_path() / ("mrd_hil_" + s.name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto controller_config = dir / "controller.toml";
  const auto plant_config = dir / "plant.toml";
  const auto telemetry = dir / "telemetry.csv";
  const auto plant_log = dir / "plant.csv";
  write_file(controller_config, s.controller_toml);
  write_file(plant_config, "[plant]\ncontroller_config = \"" + controller_config.string() +
                               "\"\nlog = \"" + plant_log.string() + "\"\n" + s.plant_toml);

  std::vector<std::string> plant_args{binary("MRD_PLANT", MRD_PLANT_BINARY), "--config", plant_config.string()};
  const std::vector<std::string> controller_args{binary("MRD_CONTROLLER", MRD_CONTROLLER_BINARY), "--config",
                                                 controller_config.string(), "--duration",
                                                 std::to_string(s.controller_duration), "--telemetry",
                                                 telemetry.string()};
  std::optional<ChildProcess> plant;
  std::optional<ChildProcess> controller;
  if (s.plant_delay >= 0.0) {
    // The controller cannot be told a port the plant has not picked yet: the run picks it.
    const int port = free_tcp_port();
    if (port <= 0) {
      r.failure = "no free TCP port";
      return r;
    }
    write_file(controller_config, s.controller_toml + "\n[modbus.tcp]\nport = " + std::to_string(port) + "\n");
    plant_args.insert(plant_args.end(), {"--port", std::to_string(port)});
    controller.emplace(controller_args);
    // The late start is the scenario, not a wait for an event: the controller's output is read
    // meanwhile.
    const auto plant_at = std::chrono::steady_clock::now() + std::chrono::duration<double>(s.plant_delay);
    while (std::chrono::steady_clock::now() < plant_at &&
           controller->read_for(std::chrono::ceil<std::chrono::milliseconds>(plant_at - std::chrono::steady_clock::now()))) {
    }
    plant.emplace(plant_args);
    if (!plant->started()) {
      r.failure = "cannot start mrd-plant";
      return r;
    }
  } else {
    if (s.ephemeral_port) plant_args.insert(plant_args.end(), {"--port", "0"});
    plant.emplace(plant_args);
    if (!plant->started()) {
      r.failure = "cannot start mrd-plant";
      return r;
    }
    if (s.ephemeral_port) {
      const auto port = plant->wait_for_line(std::regex(R"(modbus tcp [0-9.]+:(\d+))"), 10s);
      if (!port) {
        r.failure = "mrd-plant never listened:\n" + plant->output();
        return r;
      }
      // The controller reads the port the plant got; the rest of its config is unchanged.
      write_file(controller_config, s.controller_toml + "\n[modbus.tcp]\nport = " + (*port)[1] + "\n");
    }
    if (!plant->wait_for_line(std::regex("mrd-plant: ready"), 10s)) {
      r.failure = "mrd-plant never got ready:\n" + plant->output();
      return r;
    }
    controller.emplace(controller_args);
  }
  if (s.while_running) r.observed = s.while_running(*controller);
  const auto limit = std::chrono::milliseconds(static_cast<long>(s.controller_duration * 1000.0)) + 20s;
  const auto controller_exit = controller->wait_exit(limit);
  plant->signal(SIGTERM);
  const auto plant_exit = plant->wait_exit(20s);
  r.controller_output = controller->output();
  r.plant_output = plant->output();
  if (!controller_exit || !plant_exit) {
    r.failure = "a process did not exit in time:\n--- controller\n" + r.controller_output +
                "--- plant\n" + r.plant_output;
    return r;
  }
  r.controller_exit = *controller_exit;
  r.plant_exit = *plant_exit;
  r.fault_origin = find_number(r.plant_output, R"(plant faults: time 0 is plant log time_s ([0-9.]+) s)").value_or(0.0);
  try {
    auto log = tools::read_telemetry_csv(telemetry.string());
    r.telemetry = std::move(log.rows);
    r.plant_log = record::read_recorded_run(plant_log.string());
    // The two files' time origins, from the files themselves (as mrd-hil-report joins them).
    if (!log.time_origin || !r.plant_log.time_origin) {
      r.failure = "no time-origin line in" + std::string(log.time_origin ? "" : " " + telemetry.string()) +
                  (r.plant_log.time_origin ? "" : " " + plant_log.string()) + "\n--- controller\n" +
                  r.controller_output + "--- plant\n" + r.plant_output;
      return r;
    }
    r.controller_t0 = *log.time_origin;
    r.offset = *log.time_origin - *r.plant_log.time_origin;
  } catch (const record::InputError& e) {
    r.failure = e.what();
  }
  return r;
}

std::string transitions(const HilResult& r) {
  std::string out;
  for (const auto& c : tools::state_changes(r.telemetry)) {
    out += "  " + to_string(c) + " fault clock t " + std::to_string(c.time + r.offset - r.fault_origin) + "\n";
  }
  return out;
}

// What the telemetry shows of the periods' health: each row's sample check where it changes
// (a run of good periods that never grows long enough shows where it broke).
std::string sample_checks(const HilResult& r) {
  std::string out;
  for (std::size_t i = 0; i < r.telemetry.size(); ++i) {
    const auto& row = r.telemetry[i];
    const bool changed = i == 0 || row.sample != r.telemetry[i - 1].sample || row.overruns > 0;
    if (!changed) continue;
    out += "  cycle " + std::to_string(row.cycle) + ": " + row.sample +
           (row.overruns > 0 ? ", overruns " + std::to_string(row.overruns) : "") + ", setpoint " +
           std::to_string(row.setpoint) + " A, measured " + std::to_string(row.measured_current) + " A\n";
  }
  return out;
}

std::string diagnosis(const HilResult& r) {
  return "transitions:\n" + transitions(r) + "sample checks where they change:\n" + sample_checks(r) +
         "--- controller\n" + r.controller_output + "--- plant\n" +
         r.plant_output;
}

}  // namespace mrd::test
