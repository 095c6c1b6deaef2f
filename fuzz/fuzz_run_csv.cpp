// libFuzzer target: the recorded-run reader on text (record/run_reader: parse_recorded_run, which
// hands delimited text to parse_run_csv). Any text, read as the project's own format, through a
// column mapping by name or by position, or with a constant current and a sample rate; the
// delimiter (comma, semicolon with decimal commas, tab, blanks) comes from the first line. The
// only acceptable failure is InputError; a run it accepts must pass check_run.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/run_invariants.hpp"
#include "record/csv.hpp"
#include "record/run_columns.hpp"
#include "record/run_reader.hpp"

namespace {

mrd::record::RunReadOptions options_for(std::uint8_t selector) {
  mrd::record::RunReadOptions options;
  switch (selector % 4) {
    case 1:
      options.columns = mrd::record::parse_column_mapping("t=time_s,D=displacement_cm,Y=voltage_V,F=force_N");
      break;
    case 2:
      options.columns = mrd::record::parse_column_mapping("1=time_s,2=displacement_mm,3=-force_kN");
      options.current = 0.5;
      break;
    case 3:
      options.columns = mrd::record::parse_column_mapping("2=displacement_mm");
      options.current = 1.0;
      options.sample_rate = 1000.0;
      break;
    default:
      break;
  }
  return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto options = options_for(data[0]);
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    mrd::fuzz::check_run(mrd::record::parse_recorded_run(text, "fuzz.csv", options));
  } catch (const mrd::record::InputError&) {
  }
  return 0;
}
