#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "runtime/telemetry_queue.hpp"
#include "hal/clock.hpp"
#include "hal/io_thread.hpp"
#include "hal/status.hpp"

namespace mrd::runtime {

// The non-real-time side of telemetry: a thread that drains the ring every flush period and
// writes CSV. It may block on the disk; the loop never waits for it.
class CsvTelemetryWriter {
 public:
  CsvTelemetryWriter(TelemetryQueue& queue, double flush_period_s)
      : queue_(queue), flush_period_s_(flush_period_s) {}
  ~CsvTelemetryWriter() { stop(); }
  CsvTelemetryWriter(const CsvTelemetryWriter&) = delete;
  CsvTelemetryWriter& operator=(const CsvTelemetryWriter&) = delete;

  // Opens `path`, writes the header and starts the thread.
  [[nodiscard]] hal::StartResult start(const std::string& path);
  // Drains what is left, closes the file, joins the thread.
  void stop();

  [[nodiscard]] std::uint64_t written() const { return written_.load(std::memory_order_relaxed); }
  // The CSV's t = 0 on the loop's clock (CLOCK_MONOTONIC in the controller), once a record is
  // written; read it after stop(). Another process on the same host joins its log by it.
  [[nodiscard]] std::optional<hal::Timestamp> start_time() const { return start_; }
  static const char* header();
  // One CSV line (with '\n') into buf, time counted from `start`; returns the length.
  static int format(const TelemetryRecord& r, hal::Timestamp start, char* buf, std::size_t size);

 private:
  void drain_once();

  TelemetryQueue& queue_;
  double flush_period_s_;
  std::FILE* file_ = nullptr;
  std::optional<hal::Timestamp> start_;  // the first record's time: the CSV's t = 0
  std::atomic<std::uint64_t> written_{0};
  hal::IoThread thread_;
};

}  // namespace mrd::runtime
