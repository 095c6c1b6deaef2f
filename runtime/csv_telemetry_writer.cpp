#include "runtime/csv_telemetry_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <cmath>
#include <cstring>

#include "common/time_origin.hpp"
#include "control/sample_check.hpp"
#include "control/supervisor.hpp"

namespace mrd::runtime {

namespace {
#define MRD_TELEMETRY_COLUMNS                                                                    \
  "cycle,time_s,displacement_mm,sample,measured_current_A,scheduled_current_A,"                  \
  "law_current_A,setpoint_A,target_B_T,B_T,velocity_mm_s,force_kN,state,trigger,overruns,"       \
  "enable,latched,recoveries"
constexpr const char* kHeader = MRD_TELEMETRY_COLUMNS "\n";
// Force mode: the demand the law used, Eq. 12's yield force at its target, the demand's check,
// the inverse's flags, the load-cell correction's scale and its frozen periods
// (docs/FORCE-CONTROL.md).
constexpr const char* kForceHeader =
    MRD_TELEMETRY_COLUMNS ",demand_N,yield_force_N,demand,clipped,reached,force_scale,load_cell_frozen\n";
#undef MRD_TELEMETRY_COLUMNS

// The force columns after the line `format` wrote (its '\n' replaced).
int append_force_columns(const TelemetryRecord& r, char* buf, std::size_t size, int length) {
  if (length <= 0 || static_cast<std::size_t>(length) >= size) return length;
  const auto check = to_string(static_cast<control::SampleCheck>(r.demand_check));
  const int more = std::snprintf(buf + length - 1, size - static_cast<std::size_t>(length) + 1,
                                 ",%.6g,%.6g,%.*s,%d,%d,%.6g,%u\n", r.demand, r.yield_force,
                                 static_cast<int>(check.size()), check.data(), r.clipped ? 1 : 0,
                                 r.reached ? 1 : 0, r.force_scale, static_cast<unsigned>(r.load_cell_frozen));
  return more < 0 ? more : length - 1 + more;
}
}  // namespace

const char* CsvTelemetryWriter::header() { return kHeader; }
const char* CsvTelemetryWriter::force_header() { return kForceHeader; }

int CsvTelemetryWriter::format(const TelemetryRecord& r, hal::Timestamp start, char* buf,
                               std::size_t size, bool force_columns) {
  const double t = std::chrono::duration<double>(r.time - start).count();
  const auto sample = to_string(static_cast<control::SampleCheck>(r.sample));
  const auto state = to_string(static_cast<control::SupervisorState>(r.state));
  const auto trigger = to_string(static_cast<control::Trigger>(r.trigger));
  const int length = std::snprintf(buf, size, "%llu,%.6f,%.4f,%.*s,%.5g,%.4g,%.5g,%.5g,%.5g,%.5g,%.5g,%.5g,%.*s,%.*s,%u,%d,%d,%llu\n",
                       static_cast<unsigned long long>(r.cycle), t, r.displacement * 1e3,
                       static_cast<int>(sample.size()), sample.data(), r.measured_current,
                       r.scheduled_current, r.law_current, r.setpoint, r.target_B, r.B,
                       r.velocity * 1e3, r.force * 1e-3, static_cast<int>(state.size()),
                       state.data(), static_cast<int>(trigger.size()), trigger.data(), r.overruns,
                       r.enable ? 1 : 0, r.latched ? 1 : 0, static_cast<unsigned long long>(r.recoveries));
  return force_columns ? append_force_columns(r, buf, size, length) : length;
}

std::string CsvTelemetryWriter::run_file(const std::string& path, unsigned n) {
  const std::filesystem::path p(path);
  char number[16];
  std::snprintf(number, sizeof number, "-%04u", n);
  return (p.parent_path() / (p.stem().string() + number + p.extension().string())).string();
}

namespace {

// The highest run number among the files beside `path` named as run_file names them.
unsigned last_run(const std::string& path) {
  const std::filesystem::path p(path);
  const std::string stem = p.stem().string() + "-";
  const std::string extension = p.extension().string();
  unsigned last = 0;
  std::error_code error;
  const auto dir = p.parent_path().empty() ? std::filesystem::path(".") : p.parent_path();
  for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(stem) || !name.ends_with(extension)) continue;
    const std::string digits = name.substr(stem.size(), name.size() - stem.size() - extension.size());
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    last = std::max(last, static_cast<unsigned>(std::stoul(digits)));
  }
  return last;
}

}  // namespace

int CsvTelemetryWriter::open_file(const std::string& path, int flags) {
  // O_NOFOLLOW: a symbolic link put where the file goes after the config was checked must not
  // redirect the writes out of telemetry.directory.
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_NOFOLLOW | O_CLOEXEC | flags, 0640);
  file_ = fd >= 0 ? fdopen(fd, "w") : nullptr;
  if (file_ == nullptr) {
    const int error = errno;
    if (fd >= 0) close(fd);
    return error;
  }
  path_ = path;
  return 0;
}

namespace {
hal::StartResult cannot_open(const std::string& path, int error) {
  return hal::StartResult::failure("cannot open telemetry file " + path + ": " + std::strerror(error));
}
}  // namespace

hal::StartResult CsvTelemetryWriter::start(const TelemetryConfig& config) {
  max_bytes_ = static_cast<std::uint64_t>(std::max<std::int64_t>(config.max_bytes, 0));
  const std::string path = config.resolved_path();
  if (!config.per_run) {
    const int error = open_file(path, O_TRUNC);
    return error == 0 ? start_thread() : cannot_open(path, error);
  }
  // O_EXCL: a file that appeared since the directory was read (another start) is never
  // truncated; this start takes the next number.
  const unsigned first = last_run(path) + 1;
  for (unsigned n = first; n < first + 100; ++n) {
    const int error = open_file(run_file(path, n), O_EXCL);
    if (error == 0) return start_thread();
    if (error != EEXIST) return cannot_open(run_file(path, n), error);
  }
  return cannot_open(run_file(path, first), EEXIST);
}

hal::StartResult CsvTelemetryWriter::start(const std::string& path) {
  const int error = open_file(path, O_TRUNC);
  return error == 0 ? start_thread() : cannot_open(path, error);
}

hal::StartResult CsvTelemetryWriter::start_thread() {
  const char* columns = force_columns_ ? force_header() : header();
  write_line(columns, std::strlen(columns));
  const auto pause = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(flush_period_s_));
  thread_.start("mrd-telemetry", [this, pause] {
    while (thread_.wait_for(pause)) drain_once();
  });
  return hal::StartResult::success();
}

bool CsvTelemetryWriter::write_line(const char* line, std::size_t length) {
  if (max_bytes_ > 0 && bytes_ + length > max_bytes_) return false;
  std::fwrite(line, 1, length, file_);
  bytes_ += length;
  return true;
}

void CsvTelemetryWriter::drain_once() {
  char line[512];
  std::uint64_t written = 0;
  std::uint64_t capped = 0;
  queue_.drain([&](const TelemetryRecord& r) {
    if (!start_) {
      start_ = r.time;
      const int len = format_time_origin(std::chrono::duration<double>(r.time).count(),
                                         line, sizeof line);
      if (len > 0) write_line(line, static_cast<std::size_t>(len));
    }
    const int len = format(r, *start_, line, sizeof line, force_columns_);
    if (len > 0 && write_line(line, std::min(static_cast<std::size_t>(len), sizeof line - 1))) {
      ++written;
    } else {
      ++capped;
    }
  });
  if (written > 0) {
    std::fflush(file_);
    written_.fetch_add(written, std::memory_order_relaxed);
  }
  if (capped > 0) capped_.fetch_add(capped, std::memory_order_relaxed);
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
