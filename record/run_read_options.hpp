#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "hal/can/socketcan_config.hpp"
#include "record/run_columns.hpp"

namespace mrd::record {

// How to read a run file. Everything a foreign file does not say for itself.
struct RunReadOptions {
  // A foreign CSV's columns. Without it, the header must name each column with its unit.
  std::optional<ColumnMapping> columns;
  // A constant coil current [A] for runs that did not log one (constant-current tests).
  std::optional<double> current;
  // The constant current from the file name: 25mm0x25Hz0x5A.txt -> 0.5 A.
  bool current_from_name = false;
  // [Hz], for files without a time column: sample i is at i / sample_rate.
  std::optional<double> sample_rate;
  // candump logs: which CAN ids carry the LVDT, the command and the feedback (the
  // controller's own `can` table, so a moved id reads the same as it is sent).
  hal::can::SocketCanConfig can;
};

// The constant coil current the options give for the file `name`, and where it came from
// ("--current 0.5 A" or "file name: 0.5 A"); nullopt when they give none.
struct ConstantCurrent {
  double amps = 0.0;
  std::string source;
};
// Throws InputError when --current-from-name finds no current in the name.
[[nodiscard]] std::optional<ConstantCurrent> constant_current(const RunReadOptions& options,
                                                              std::string_view name);

// The coil current in a file name that ends in <current>A, with x (or p) for the decimal
// point: ".../25mm0x25Hz0x5A.txt" -> 0.5, "5mm3Hz1A.txt" -> 1. nullopt when there is none.
[[nodiscard]] std::optional<double> current_from_file_name(std::string_view path);

}  // namespace mrd::record
