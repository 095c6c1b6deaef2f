#include "telemetry/csv_telemetry_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <cmath>
#include <cstring>

#include "common/time_origin.hpp"
#include "telemetry/bounded_write.hpp"
#include "telemetry/telemetry_columns.hpp"

namespace mrd::telemetry {

std::string CsvTelemetryWriter::column_line(std::span<const TelemetryColumn> columns, bool force_columns) {
  std::string line;
  for (const TelemetryColumn& c : columns) {
    if (c.force_mode && !force_columns) break;
    if (!line.empty()) line.push_back(',');
    line.append(c.name);
  }
  return line + "\n";
}

// Built once, in start_thread, before the loop's first record.
const char* CsvTelemetryWriter::header() {
  static const std::string line = column_line(kTelemetryColumns, false);
  return line.c_str();
}

const char* CsvTelemetryWriter::force_header() {
  static const std::string line = column_line(kTelemetryColumns, true);
  return line.c_str();
}

int CsvTelemetryWriter::format(const TelemetryRecord& r, hal::Timestamp start, char* buf,
                               std::size_t size, bool force_columns) {
  return format(kTelemetryColumns, r, start, buf, size, force_columns);
}

int CsvTelemetryWriter::format(std::span<const TelemetryColumn> columns, const TelemetryRecord& r,
                               hal::Timestamp start, char* buf, std::size_t size, bool force_columns) {
  const double t = std::chrono::duration<double>(r.time - start).count();
  std::size_t length = 0;
  for (const TelemetryColumn& c : columns) {
    if (c.force_mode && !force_columns) break;  // force mode's columns come last
    if (length > 0) {
      if (length + 1 >= size) return -1;
      buf[length++] = ',';
    }
    const int n = c.write(r, t, buf + length, size - length);
    if (n < 0 || length + static_cast<std::size_t>(n) >= size) return -1;  // a line cut short is no line
    length += static_cast<std::size_t>(n);
  }
  if (length + 1 >= size) return -1;
  buf[length++] = '\n';
  buf[length] = '\0';
  return static_cast<int>(length);
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
  // redirect the writes out of telemetry.directory. O_NONBLOCK: a FIFO without a reader is
  // refused (ENXIO) rather than waited for, and a reader that stops draining costs a timeout.
  fd_ = open(path.c_str(), O_WRONLY | O_CREAT | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK | flags, 0640);
  if (fd_ < 0) return errno;
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
  batch_.reserve(kBatchBytes + 512);
  (void)header();  // the column lines are built here, not with the first record
  (void)force_header();
  header_pending_ = true;
  const auto pause = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(flush_period_s_));
  thread_.start("mrd-telemetry", [this, pause] {
    while (thread_.wait_for(pause)) drain_once(write_timeout_);
  });
  return hal::StartResult::success();
}

bool CsvTelemetryWriter::add_line(const char* line, std::size_t length, bool record) {
  if (max_bytes_ > 0 && bytes_ + length > max_bytes_) return false;
  batch_.append(line, length);
  lines_.push_back({batch_.size(), record});
  bytes_ += length;
  return true;
}

void CsvTelemetryWriter::fail(int error) {
  failures_.fetch_add(1, std::memory_order_relaxed);
  last_error_.store(error, std::memory_order_relaxed);
}

void CsvTelemetryWriter::write_batch(std::chrono::milliseconds wait) {
  if (batch_.empty()) return;
  const auto result = write_before(fd_, batch_, std::chrono::steady_clock::now() + (stalled_ ? std::chrono::milliseconds{0} : wait));
  // Whole lines written count; a line the file took part of stays (its rest goes first next
  // time, so the file never holds half a line followed by another); the lines after it are lost.
  std::uint64_t written = 0;
  std::uint64_t lost = 0;
  std::size_t begin = 0;
  std::optional<Line> started;
  std::size_t rest_begin = 0;
  for (const Line& line : lines_) {
    if (line.end <= result.written) {
      written += line.record ? 1 : 0;
    } else if (begin < result.written || (begin == 0 && carried_)) {
      rest_begin = std::max(begin, result.written);
      started = line;
    } else {
      lost += line.record ? 1 : 0;
      bytes_ -= line.end - begin;
    }
    begin = line.end;
  }
  batch_.erase(started ? started->end : 0);
  batch_.erase(0, rest_begin);
  lines_.clear();
  carried_ = started.has_value();
  if (started) lines_.push_back({batch_.size(), started->record});
  if (written > 0) written_.fetch_add(written, std::memory_order_relaxed);
  if (lost > 0) lost_.fetch_add(lost, std::memory_order_relaxed);
  if (result.error != 0) fail(result.error);
  stalled_ = result.error != 0;
}

void CsvTelemetryWriter::drain_once(std::chrono::milliseconds wait) {
  char line[512];
  std::uint64_t capped = 0;
  queue_.drain([&](const TelemetryRecord& r) {
    if (!start_) {
      start_ = r.time;
      const int len = format_time_origin(std::chrono::duration<double>(r.time).count(),
                                         line, sizeof line);
      if (len > 0) add_line(line, std::min(static_cast<std::size_t>(len), sizeof line - 1), false);
      add_header();
    }
    const int len = format(r, *start_, line, sizeof line, force_columns_);
    if (len <= 0 || !add_line(line, std::min(static_cast<std::size_t>(len), sizeof line - 1), true)) ++capped;
    if (batch_.size() >= kBatchBytes) write_batch(wait);
  });
  write_batch(wait);
  if (capped > 0) capped_.fetch_add(capped, std::memory_order_relaxed);
}

void CsvTelemetryWriter::add_header() {
  if (!header_pending_) return;
  const char* columns = force_columns_ ? force_header() : header();
  add_line(columns, std::strlen(columns), false);
  header_pending_ = false;
}

void CsvTelemetryWriter::stop() {
  thread_.stop();
  if (fd_ < 0) return;
  drain_once(write_timeout_);  // the loop has stopped: whatever is left is the tail of the run
  if (header_pending_) {  // no record came: the file still says what it would have held
    add_header();
    write_batch(write_timeout_);
  }
  if (carried_ && lines_.front().record) lost_.fetch_add(1, std::memory_order_relaxed);  // never completed
  batch_.clear();
  lines_.clear();
  carried_ = false;
  if (::close(fd_) != 0 && errno != EINTR) fail(errno);  // NFS reports a lost write here
  fd_ = -1;
}

}  // namespace mrd::telemetry
