#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "record/csv.hpp"
#include "record/recorded_run.hpp"
#include "record/run_columns.hpp"
#include "record/row_screen.hpp"
#include "record/run_read_options.hpp"

namespace mrd::record {

// Where a reader is in its file, as its messages name it: text files count lines
// ("run.csv:12: column 'F': ..."), .mat files samples ("run.mat: sample 12: variable 'F': ...").
enum class RowPlace : std::uint8_t { kLine, kSample };

// Turns a table of numbers into a RecordedRun, whatever file held it (delimited text, a .mat
// file): maps its columns onto the run's quantities (the project's unit names, or
// options.columns), checks that the run has time, displacement and a coil signal, converts to SI
// and keeps each row or sets it aside (RecordedRun::SetAsideRow: duplicate, time_conflict,
// non_finite). The readers find the columns and the cells; this is what they share.
class RunAssembler {
 public:
  struct Column {
    std::string label;      // header or variable name, or the 1-based position
    std::size_t index = 0;  // in the reader's row
    ColumnUnit unit;
  };

  RunAssembler(const std::string& name, const RunReadOptions& options, RowPlace place);

  // The table's column names: each mapped by options.columns (the others are ignored, in a
  // note), or without it the project's own names with units (a name it does not know is an
  // error), or the controller's telemetry.
  void map_names(const std::vector<std::string_view>& names);
  // A table without names: options.columns by position, `width` cells a row.
  void map_positions(std::size_t width);
  // Once mapped, before any row: time (or --sample-rate), displacement and a coil signal.
  void check_required();

  // The cells add_row takes, in its order.
  [[nodiscard]] const std::vector<Column>& columns() const { return used_; }

  // The value of columns()[k] in SI; `written` is the cell as the file has it, for the error when
  // the conversion overflows.
  [[nodiscard]] double to_internal(std::size_t k, double value, std::string_view written) const;
  // One row at `position` (its line or sample): values[k] for columns()[k], in SI, NaN from the
  // first empty or non-finite cell on (the row is set aside naming that column).
  void add_row(const std::vector<double>& values, std::size_t position);
  // The run; `start` is where the table starts (the header line), for the error of a run with
  // fewer than two samples.
  [[nodiscard]] RecordedRun finish(std::size_t start);

  // An error at the current position (the row last given, or set_position's).
  [[nodiscard]] InputError fail(std::string_view column, const std::string& message) const;
  void set_position(std::size_t position) { position_ = position; }
  void note(std::string text) { run_.notes.push_back(std::move(text)); }

 private:
  void use(std::string label, std::size_t index, const ColumnUnit& unit);
  void map_own_names(const std::vector<std::string_view>& names);
  void map_telemetry(const std::vector<std::string_view>& names);
  [[nodiscard]] const Column* find(RunQuantity q) const;
  [[nodiscard]] std::vector<double>& channel(RunQuantity q);
  void keep_row(const std::vector<double>& values, std::size_t position);
  [[nodiscard]] bool same_as_last_row(const std::vector<double>& values);
  void drop_last_row(const std::string& column);
  void set_aside(std::string_view reason, const std::string& column);
  void note_set_aside_rows();
  [[nodiscard]] std::string_view where() const { return place_ == RowPlace::kLine ? "line" : "sample"; }

  const std::string& name_;
  const RunReadOptions& options_;
  RowPlace place_;
  std::size_t position_ = 0;
  RecordedRun run_;
  std::vector<Column> used_;
  std::vector<std::string> names_;
  std::optional<ConstantCurrent> constant_;
  std::size_t last_position_ = 0;  // of the last row kept
  // The row just set aside for going back, with its position: kept after all if the next row
  // shows that the row before it strayed.
  struct PendingRow {
    std::vector<double> values;
    std::size_t position = 0;
  };
  std::optional<PendingRow> conflict_;
  RowScreen screen_;
};

}  // namespace mrd::record
