#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mrd::record {

// What one column of a recorded run holds.
enum class RunQuantity : std::uint8_t {
  kTime,
  kDisplacement,
  kCurrent,
  kVoltage,  // the driver's command voltage, when the coil current was not logged
  kForce,
  kVelocity,
  kFluxDensity,
  kTemperature,
  // A .mat file's scalars that give the time where the run has no time vector.
  kSampleTime,
  kSampleRate,
};
[[nodiscard]] std::string_view to_string(RunQuantity q);

// A column's unit, named the project's way (`displacement_mm`). Inside the code the value is
// file value * scale + offset: SI, except temperature, which stays in degrees Celsius
// (RecordedRun says why).
struct ColumnUnit {
  RunQuantity quantity = RunQuantity::kTime;
  std::string_view name;  // "displacement_mm"
  double scale = 1.0;
  double offset = 0.0;

  [[nodiscard]] double to_internal(double file_value) const { return file_value * scale + offset; }
};

// The unit a column name states. Either `unit` is set, or `error` says what is wrong:
// "unknown unit 'in' for displacement; expected displacement_m, displacement_mm or
// displacement_cm", or "unknown column; expected time_s, ...".
struct UnitLookup {
  std::optional<ColumnUnit> unit;
  std::string error;
};
[[nodiscard]] UnitLookup column_unit(std::string_view name);

// Every unit name the readers know, for help texts: "time_s, time_ms, displacement_m, ...".
[[nodiscard]] std::string known_unit_names();

// How the columns of a foreign file map onto the run: `--columns t=time_s,D=displacement_cm`
// (by header name) or `--columns 1=time_s,2=displacement_mm` (by 1-based position, for files
// without a header). Columns the mapping leaves out are ignored. A leading '-' on the unit
// (`F=-force_N`) flips the sign of a file whose convention is the opposite of ours.
struct ColumnMapping {
  struct Entry {
    std::string source;        // header name, or the position as written
    std::size_t position = 0;  // 1-based; only when by_position
    ColumnUnit unit;
  };
  std::vector<Entry> entries;
  bool by_position = false;  // every source is a position; the file has no header line
};

// Throws InputError("--columns: ...") naming the entry that is wrong.
[[nodiscard]] ColumnMapping parse_column_mapping(std::string_view text);

}  // namespace mrd::record
