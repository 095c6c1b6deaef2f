#include "record/run_reader.hpp"

#include <fstream>

#include "record/candump_log.hpp"
#include "record/csv.hpp"
#include "record/run_csv.hpp"
#include "record/run_mat.hpp"

namespace mrd::record {

namespace {

// The file's first bytes, enough for a .mat header's text; "" when it cannot be opened (the
// text reader then says so).
std::string head_of(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::string head(128, '\0');
  file.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(file ? head.size() : static_cast<std::size_t>(file.gcount()));
  return head;
}

}  // namespace

RecordedRun parse_recorded_run(std::string_view text, const std::string& name,
                               const RunReadOptions& options) {
  if (starts_like_mat_file(text))
    throw InputError(name + ": a MATLAB .mat file; read it from its file (read_recorded_run)");
  LineReader lines(text, name);
  const auto first = lines.next();
  const bool candump = first && first->find_first_not_of(" \t") != std::string_view::npos &&
                       (*first)[first->find_first_not_of(" \t")] == '(';
  return candump ? parse_candump(text, name, options).run : parse_run_csv(text, name, options);
}

RecordedRun read_recorded_run(const std::string& path, const RunReadOptions& options) {
  if (starts_like_mat_file(head_of(path))) return read_mat_run(path, options);
  return parse_recorded_run(read_text_file(path), path, options);
}

}  // namespace mrd::record
