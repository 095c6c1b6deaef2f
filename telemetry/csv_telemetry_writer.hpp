#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "telemetry/telemetry_columns.hpp"
#include "telemetry/telemetry_config.hpp"
#include "telemetry/telemetry_queue.hpp"
#include "hal/clock.hpp"
#include "hal/io_thread.hpp"
#include "hal/status.hpp"

namespace mrd::telemetry {

// The non-real-time side of telemetry: a thread that drains the ring every flush period and
// writes CSV. The loop never waits for it, and it never waits long for the file: the file is
// open O_NONBLOCK and each pass waits at most `write_timeout` for a file (a FIFO whose reader
// stopped draining) that takes nothing, then counts the records it could not write as lost.
// After such a timeout the passes wait no more until a pass writes everything again, so stop()
// returns within about two write timeouts whatever the reader does.
class CsvTelemetryWriter {
 public:
  static constexpr std::chrono::milliseconds kWriteTimeout{1000};
  static constexpr std::size_t kBatchBytes = 64 * 1024;  // written once this much is formatted

  // `force_columns`: force mode's columns after the others (table4 files are unchanged).
  CsvTelemetryWriter(TelemetryQueue& queue, double flush_period_s, bool force_columns = false,
                     std::chrono::milliseconds write_timeout = kWriteTimeout)
      : queue_(queue), flush_period_s_(flush_period_s), force_columns_(force_columns), write_timeout_(write_timeout) {}
  ~CsvTelemetryWriter() { stop(); }
  CsvTelemetryWriter(const CsvTelemetryWriter&) = delete;
  CsvTelemetryWriter& operator=(const CsvTelemetryWriter&) = delete;

  // Opens `path` (truncated) and starts the thread. The file opens with the time origin (a '#'
  // comment line), then the column line: written with the first record, or at stop() when none
  // came, so that pandas.read_csv(f, comment='#') reads the file as it is.
  [[nodiscard]] hal::StartResult start(const std::string& path);
  // As above on the config's file: with per_run a new numbered file beside the earlier runs'
  // (never one that exists), and at most max_bytes written.
  [[nodiscard]] hal::StartResult start(const TelemetryConfig& config);
  // Joins the thread, drains what is left, closes the file: bounded in time (see above).
  void stop();

  [[nodiscard]] std::uint64_t written() const { return written_.load(std::memory_order_relaxed); }
  // Records the size cap kept out of the file: written + capped + lost + the ring's dropped = offered.
  [[nodiscard]] std::uint64_t capped() const { return capped_.load(std::memory_order_relaxed); }
  // Records the file did not take: a write error (ENOSPC, EIO, EPIPE) or the write timeout.
  [[nodiscard]] std::uint64_t lost() const { return lost_.load(std::memory_order_relaxed); }
  // Failed writes and closes (the header's and the time origin's among them): > 0, the file is
  // incomplete.
  [[nodiscard]] std::uint64_t failures() const { return failures_.load(std::memory_order_relaxed); }
  // The errno of the latest failure (ETIMEDOUT: the file took nothing within the timeout); 0: none.
  [[nodiscard]] int last_error() const { return last_error_.load(std::memory_order_relaxed); }
  // The file being written (after start()).
  [[nodiscard]] const std::string& path() const { return path_; }
  // The CSV's t = 0 on the loop's clock (CLOCK_MONOTONIC in the controller), once a record is
  // written; read it after stop(). Another process on the same host joins its log by it.
  [[nodiscard]] std::optional<hal::Timestamp> start_time() const { return start_; }
  // The column lines (telemetry/telemetry_columns.hpp), '\n' ended.
  static const char* header();
  static const char* force_header();  // header() with force mode's columns
  // One CSV line (with '\n') into buf, time counted from `start`; returns the length, or -1 when
  // it does not fit (no line cut short).
  static int format(const TelemetryRecord& r, hal::Timestamp start, char* buf, std::size_t size,
                    bool force_columns = false);
  // The same from another table: what a test of the table itself writes with.
  static int format(std::span<const TelemetryColumn> columns, const TelemetryRecord& r, hal::Timestamp start,
                    char* buf, std::size_t size, bool force_columns);
  static std::string column_line(std::span<const TelemetryColumn> columns, bool force_columns);
  // The file a run numbered `n` writes for `path`: "dir/run.csv" -> "dir/run-0007.csv".
  static std::string run_file(const std::string& path, unsigned n);

 private:
  int open_file(const std::string& path, int flags);  // 0 or the errno
  hal::StartResult start_thread();
  bool add_line(const char* line, std::size_t length, bool record);  // false: over the cap, not added
  void drain_once(std::chrono::milliseconds wait);
  void add_header();  // after the origin line: a reader that skips comments then sees the columns first
  void write_batch(std::chrono::milliseconds wait);
  void fail(int error);

  // A line of the batch: where it ends, and whether it is a record (not the header).
  struct Line {
    std::size_t end;
    bool record;
  };

  TelemetryQueue& queue_;
  double flush_period_s_;
  bool force_columns_;
  std::chrono::milliseconds write_timeout_;
  int fd_ = -1;
  std::string batch_;        // the pass's lines, a partly written line's rest first
  std::vector<Line> lines_;  // writer thread only, like batch_
  bool carried_ = false;     // batch_ starts with the rest of a line the file took part of
  bool stalled_ = false;     // the last write failed or timed out: do not wait again until one completes
  bool header_pending_ = false;  // the column line is still to come (after the origin)
  std::optional<hal::Timestamp> start_;  // the first record's time: the CSV's t = 0
  std::string path_;
  std::uint64_t max_bytes_ = 0;  // 0: no cap
  std::uint64_t bytes_ = 0;      // writer thread only
  std::atomic<std::uint64_t> written_{0};
  std::atomic<std::uint64_t> capped_{0};
  std::atomic<std::uint64_t> lost_{0};
  std::atomic<std::uint64_t> failures_{0};
  std::atomic<int> last_error_{0};
  hal::IoThread thread_;
};

}  // namespace mrd::telemetry
