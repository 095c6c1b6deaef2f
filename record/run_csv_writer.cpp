#include "record/run_csv_writer.hpp"

#include <array>
#include <cstdio>

namespace mrd::record {

namespace {

struct Column {
  const char* header;
  double per_si;  // file unit per SI unit
  double RunCsvRow::*value;
};

// Columns in file order, and whether the layout carries each.
template <typename Visitor>
void for_each_column(const RunCsvLayout& layout, Visitor&& visit) {
  const bool voltage = layout.coil_signal == CoilSignal::kCommandVoltage;
  visit(Column{"time_s", 1.0, &RunCsvRow::time});
  visit(Column{"displacement_mm", 1e3, &RunCsvRow::displacement});
  visit(Column{voltage ? "voltage_V" : "current_A", 1.0, &RunCsvRow::coil});
  if (layout.force) visit(Column{"force_N", 1.0, &RunCsvRow::force});
  if (layout.velocity) visit(Column{"velocity_mm_s", 1e3, &RunCsvRow::velocity});
  if (layout.B) visit(Column{"B_T", 1.0, &RunCsvRow::B});
  if (layout.temperature) visit(Column{"temperature_C", 1.0, &RunCsvRow::temperature});
}

}  // namespace

std::string RunCsvWriter::header() const {
  std::string text;
  for_each_column(layout_, [&](const Column& c) { text.append(text.empty() ? "" : ",").append(c.header); });
  return text + '\n';
}

std::size_t RunCsvWriter::format_row(const RunCsvRow& row, std::span<char> buffer) const {
  if (buffer.size() < kMaxRowChars) return 0;
  std::size_t used = 0;
  for_each_column(layout_, [&](const Column& c) {
    const int n = std::snprintf(buffer.data() + used, buffer.size() - used, used ? ",%.*g" : "%.*g",
                                layout_.significant_digits, row.*c.value * c.per_si);
    if (n > 0) used += static_cast<std::size_t>(n);
  });
  buffer[used++] = '\n';
  return used;
}

void RunCsvWriter::append_row(const RunCsvRow& row, std::string& out) const {
  std::array<char, kMaxRowChars> line{};
  out.append(line.data(), format_row(row, line));
}

std::string format_run_csv(const RecordedRun& run) {
  const RunCsvLayout layout{.coil_signal = run.coil_signal,
                            .force = run.has_force(),
                            .velocity = run.has_velocity(),
                            .B = run.has_B(),
                            .temperature = run.has_temperature(),
                            .significant_digits = 12};
  const RunCsvWriter writer(layout);
  std::string text = writer.header();
  const auto at = [&](const std::vector<double>& v, std::size_t i) { return v.empty() ? 0.0 : v[i]; };
  for (std::size_t i = 0; i < run.size(); ++i) {
    writer.append_row({run.time[i], run.displacement[i], run.coil[i], at(run.force, i), at(run.velocity, i),
                       at(run.B, i), at(run.temperature, i)},
                      text);
  }
  return text;
}

}  // namespace mrd::record
