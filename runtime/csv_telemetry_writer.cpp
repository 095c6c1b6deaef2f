#include "runtime/csv_telemetry_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>

#include "control/sample_check.hpp"
#include "control/supervisor.hpp"

namespace mrd::runtime {

const char* CsvTelemetryWriter::header() {
  return "cycle,time_s,displacement_mm,sample,measured_current_A,scheduled_current_A,"
         "law_current_A,setpoint_A,target_B_T,B_T,velocity_mm_s,force_kN,state,trigger,overruns,"
         "enable,latched,recoveries\n";
}

int CsvTelemetryWriter::format(const TelemetryRecord& r, hal::Timestamp start, char* buf,
                               std::size_t size) {
  const double t = std::chrono::duration<double>(r.time - start).count();
  const auto sample = to_string(static_cast<control::SampleCheck>(r.sample));
  const auto state = to_string(static_cast<control::SupervisorState>(r.state));
  const auto trigger = to_string(static_cast<control::Trigger>(r.trigger));
  return std::snprintf(buf, size, "%llu,%.6f,%.4f,%.*s,%.5g,%.4g,%.5g,%.5g,%.5g,%.5g,%.5g,%.5g,%.*s,%.*s,%u,%d,%d,%llu\n",
                       static_cast<unsigned long long>(r.cycle), t, r.displacement * 1e3,
                       static_cast<int>(sample.size()), sample.data(), r.measured_current,
                       r.scheduled_current, r.law_current, r.setpoint, r.target_B, r.B,
                       r.velocity * 1e3, r.force * 1e-3, static_cast<int>(state.size()),
                       state.data(), static_cast<int>(trigger.size()), trigger.data(), r.overruns,
                       r.enable ? 1 : 0, r.latched ? 1 : 0, static_cast<unsigned long long>(r.recoveries));
}

hal::StartResult CsvTelemetryWriter::start(const std::string& path) {
  // O_NOFOLLOW: a symbolic link put where the file goes after the config was checked must not
  // redirect the writes out of telemetry.directory.
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0640);
  file_ = fd >= 0 ? fdopen(fd, "w") : nullptr;
  if (file_ == nullptr) {
    const int error = errno;
    if (fd >= 0) close(fd);
    return hal::StartResult::failure("cannot open telemetry file " + path + ": " + std::strerror(error));
  }
  std::fputs(header(), file_);
  const auto pause = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(flush_period_s_));
  thread_.start("mrd-telemetry", [this, pause] {
    while (thread_.wait_for(pause)) drain_once();
  });
  return hal::StartResult::success();
}

void CsvTelemetryWriter::drain_once() {
  char line[512];
  const std::size_t n = queue_.drain([&](const TelemetryRecord& r) {
    if (!start_) start_ = r.time;
    const int len = format(r, *start_, line, sizeof line);
    if (len > 0) std::fwrite(line, 1, static_cast<std::size_t>(len), file_);
  });
  if (n > 0) {
    std::fflush(file_);
    written_.fetch_add(n, std::memory_order_relaxed);
  }
}

void CsvTelemetryWriter::stop() {
  thread_.stop();
  if (file_ != nullptr) {
    drain_once();  // the loop has stopped: whatever is left is the tail of the run
    std::fclose(file_);
    file_ = nullptr;
  }
}

}  // namespace mrd::runtime
