#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "record/recorded_run.hpp"

namespace mrd::record {

// The columns a recorded-run CSV carries. Time, displacement and the coil channel always;
// force in newtons (as the readers prefer and the load cell reports); the rest when recorded.
struct RunCsvLayout {
  CoilSignal coil_signal = CoilSignal::kCurrent;
  bool force = true;
  bool velocity = false;
  bool B = false;
  bool temperature = false;
  int significant_digits = 9;  // 9 keeps a double's noise out; 12 round-trips a run exactly enough
};

// One sample in SI units; the writer converts to the file's units.
struct RunCsvRow {
  double time = 0.0;          // [s]
  double displacement = 0.0;  // [m]
  double coil = 0.0;          // [A], or [V] for CoilSignal::kCommandVoltage
  double force = 0.0;         // [N]
  double velocity = 0.0;      // [m/s]
  double B = 0.0;             // [T]
  double temperature = 0.0;   // [degC]
};

// The one writer of the project's recorded-run format (time_s, displacement_mm, current_A or
// voltage_V, force_N, velocity_mm_s, B_T, temperature_C); parse_run_csv reads what it writes.
// format_row does not allocate, so a logging thread can use it per sample.
class RunCsvWriter {
 public:
  explicit RunCsvWriter(const RunCsvLayout& layout) : layout_(layout) {}

  [[nodiscard]] std::string header() const;  // with its newline
  // Writes one row and its newline into `buffer`; returns the characters written (0 if the
  // buffer is shorter than kMaxRowChars).
  std::size_t format_row(const RunCsvRow& row, std::span<char> buffer) const;
  void append_row(const RunCsvRow& row, std::string& out) const;

  static constexpr std::size_t kMaxRowChars = 7 * 32;

 private:
  RunCsvLayout layout_;
};

// A whole RecordedRun in the format, every channel it recorded, 12 significant digits.
[[nodiscard]] std::string format_run_csv(const RecordedRun& run);

}  // namespace mrd::record
