#pragma once

#include <cstdio>
#include <string>

#include "common/single_writer_counter.hpp"
#include "hal/status.hpp"
#include "record/run_csv_writer.hpp"
#include "sim/plant/rig.hpp"

namespace mrd::plant {

// The plant's run as a recorded-run CSV (record::RunCsvWriter; mrd-replay replays it):
// time_s,displacement_mm,current_A,force_N,B_T,temperature_C. The displacement is the LVDT's
// reading before the LVDT faults, the current the one that flows in the coil, the force the
// load cell's. Buffered: a row is a formatted line in memory, written out in large blocks.
class RunLog {
 public:
  RunLog() = default;
  ~RunLog() { close(); }
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;

  [[nodiscard]] hal::StartResult open(const std::string& path);
  void write(const RigSample& s);
  // The log's time_s 0 on CLOCK_MONOTONIC (common/time_origin.hpp), once, before the first row:
  // a comment line before the column line, so that pandas.read_csv(f, comment='#') reads the file.
  void write_time_origin(double monotonic_s);
  void close();
  // Any thread: the stepping thread writes, SIGUSR1's printout on the main thread reads.
  [[nodiscard]] std::uint64_t rows() const { return rows_.get(); }

  static constexpr record::RunCsvLayout kLayout{.B = true, .temperature = true};

 private:
  // The column line, once: after the origin, which a reader wants first (pandas' comment='#'),
  // or at the first row or the close when no origin comes.
  void write_header();

  std::FILE* file_ = nullptr;
  bool header_pending_ = false;
  std::string header_;
  SingleWriterCounter rows_;
  record::RunCsvWriter writer_{kLayout};
};

}  // namespace mrd::plant
