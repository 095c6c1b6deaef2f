#include "record/run_reader.hpp"

#include "record/csv.hpp"
#include "record/candump_log.hpp"
#include "record/run_csv.hpp"

namespace mrd::record {

RecordedRun parse_recorded_run(std::string_view text, const std::string& name,
                               const RunReadOptions& options) {
  LineReader lines(text, name);
  const auto first = lines.next();
  const bool candump = first && first->find_first_not_of(" \t") != std::string_view::npos &&
                       (*first)[first->find_first_not_of(" \t")] == '(';
  return candump ? parse_candump(text, name, options).run : parse_run_csv(text, name, options);
}

RecordedRun read_recorded_run(const std::string& path, const RunReadOptions& options) {
  return parse_recorded_run(read_text_file(path), path, options);
}

}  // namespace mrd::record
