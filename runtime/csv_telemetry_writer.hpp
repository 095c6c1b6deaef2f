#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "runtime/telemetry_config.hpp"
#include "runtime/telemetry_queue.hpp"
#include "hal/clock.hpp"
#include "hal/io_thread.hpp"
#include "hal/status.hpp"

namespace mrd::runtime {

// The non-real-time side of telemetry: a thread that drains the ring every flush period and
// writes CSV. It may block on the disk; the loop never waits for it.
class CsvTelemetryWriter {
 public:
  // `force_columns`: force mode's columns after the others (table4 files are unchanged).
  CsvTelemetryWriter(TelemetryQueue& queue, double flush_period_s, bool force_columns = false)
      : queue_(queue), flush_period_s_(flush_period_s), force_columns_(force_columns) {}
  ~CsvTelemetryWriter() { stop(); }
  CsvTelemetryWriter(const CsvTelemetryWriter&) = delete;
  CsvTelemetryWriter& operator=(const CsvTelemetryWriter&) = delete;

  // Opens `path` (truncated), writes the header and starts the thread.
  [[nodiscard]] hal::StartResult start(const std::string& path);
  // As above on the config's file: with per_run a new numbered file beside the earlier runs'
  // (never one that exists), and at most max_bytes written.
  [[nodiscard]] hal::StartResult start(const TelemetryConfig& config);
  // Drains what is left, closes the file, joins the thread.
  void stop();

  [[nodiscard]] std::uint64_t written() const { return written_.load(std::memory_order_relaxed); }
  // Records the size cap kept out of the file: written + capped + the ring's dropped = offered.
  [[nodiscard]] std::uint64_t capped() const { return capped_.load(std::memory_order_relaxed); }
  // The file being written (after start()).
  [[nodiscard]] const std::string& path() const { return path_; }
  // The CSV's t = 0 on the loop's clock (CLOCK_MONOTONIC in the controller), once a record is
  // written; read it after stop(). Another process on the same host joins its log by it.
  [[nodiscard]] std::optional<hal::Timestamp> start_time() const { return start_; }
  static const char* header();
  static const char* force_header();  // header() with force mode's columns
  // One CSV line (with '\n') into buf, time counted from `start`; returns the length.
  static int format(const TelemetryRecord& r, hal::Timestamp start, char* buf, std::size_t size,
                    bool force_columns = false);
  // The file a run numbered `n` writes for `path`: "dir/run.csv" -> "dir/run-0007.csv".
  static std::string run_file(const std::string& path, unsigned n);

 private:
  int open_file(const std::string& path, int flags);  // 0 or the errno
  hal::StartResult start_thread();
  bool write_line(const char* line, std::size_t length);  // false: over the cap, not written
  void drain_once();

  TelemetryQueue& queue_;
  double flush_period_s_;
  bool force_columns_;
  std::FILE* file_ = nullptr;
  std::optional<hal::Timestamp> start_;  // the first record's time: the CSV's t = 0
  std::string path_;
  std::uint64_t max_bytes_ = 0;  // 0: no cap
  std::uint64_t bytes_ = 0;      // writer thread only
  std::atomic<std::uint64_t> written_{0};
  std::atomic<std::uint64_t> capped_{0};
  hal::IoThread thread_;
};

}  // namespace mrd::runtime
